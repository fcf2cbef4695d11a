#!/bin/sh
# A renderer that writes a PFM of the right size whose first value is NaN
# (little-endian float 0x7fc00000), the rest black.
{ printf 'PF\n%d %d\n-1.0\n' "$3" "$4"; printf '\000\000\300\177'; head -c $(($3 * $4 * 12 - 4)) /dev/zero; } >"$2"
