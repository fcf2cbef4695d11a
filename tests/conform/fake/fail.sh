#!/bin/sh
# A renderer that gives up with an error message and status 3.
echo "fake renderer: cannot read $1" >&2
exit 3
