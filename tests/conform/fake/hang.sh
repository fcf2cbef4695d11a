#!/bin/sh
# A renderer that hangs, with a child of its own in the background: the
# runner's time limit must kill both (their process group).
echo "fake renderer: hanging" >&2
sleep 300 &
echo $! >"${FAKE_PIDFILE:-/dev/null}"
sleep 300
