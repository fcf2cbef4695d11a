#!/bin/sh
# campaign.sh GEN FIRST LAST [OPTION...] - attack 25g: attack 23's campaign
# (tests/attack23/campaign.sh: what it renders and compares) with this
# folder's generators (gen_*.awk) and attack 24h's found first and this
# round's base, 34a5772 (/tmp/base25/build/refray).  Run from the
# repository root.
GEN_DIRS="tests/attack25g tests/attack24h ${GEN_DIRS:-}" BASE=${BASE:-/tmp/base25/build/refray} exec sh tests/attack23/campaign.sh "$@"
