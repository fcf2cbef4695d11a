#!/bin/sh
# A renderer that succeeds and writes nothing at OUT, only a file of
# another name in its working directory.
echo "fake renderer: done" >&2
: >elsewhere.pfm
exit 0
