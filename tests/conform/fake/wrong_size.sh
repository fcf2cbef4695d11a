#!/bin/sh
# A renderer that writes a valid PFM one pixel too wide (all black).
w=$(($3 + 1))
{ printf 'PF\n%d %d\n-1.0\n' "$w" "$4"; head -c $((w * $4 * 12)) /dev/zero; } >"$2"
