#!/bin/sh
# campaign.sh GEN FIRST LAST [OPTION...] - attack 24h: attack 23's campaign
# (tests/attack23/campaign.sh: what it renders and compares) with this
# folder's generators found first and the round's base, 91f0472
# (/tmp/base24/build/refray).  Run from the repository root.
GEN_DIRS="tests/attack24h ${GEN_DIRS:-}" BASE=${BASE:-/tmp/base24/build/refray} exec sh tests/attack23/campaign.sh "$@"
