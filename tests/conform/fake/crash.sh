#!/bin/sh
# A renderer that crashes: SIGSEGV to itself after a word on stderr.
# Arguments, as every fake here: SCENE OUT WIDTH HEIGHT.
echo "fake renderer: about to crash" >&2
kill -SEGV $$
