#!/bin/sh
# hand_campaign.sh GEN FIRST LAST [OPTION...] - attack 25g: campaign.sh
# without the counts' comparison (COUNTS=0), for a BASE older than the
# round's: the runs in the README set BASE to the old binary
# (/tmp/old-main/build/refray), whose shortcuts counted other rays.  A seed
# is printed when images or exit codes differ.  Run from the repository
# root.  Exits 1 when some seed differed.
COUNTS=0 exec sh tests/attack25g/campaign.sh "$@"
