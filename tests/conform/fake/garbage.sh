#!/bin/sh
# A renderer that writes something that is not an image at OUT.
echo "this is not an image" >"$2"
