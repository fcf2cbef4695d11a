#!/bin/sh
# repro_on_surface.sh - attack 24h, finding 1: [SHADE-SHORTCUT-HIDDEN-1]
# moves the "skipped on the surface" count (trace_stats.lights_on_surface)
# of the light samples line.  A Kd 0 mirror floor over a background of
# DBL_MAX (its mirrored colour already saturates shade_combine, so the
# point's loop is left out whatever the lights: U = +Inf, clamped to
# DBL_MAX, leaves DBL_MAX), seen straight down by an orthographic camera
# whose one ray hits [0, 0, 0] exactly, where a point light sits.  The
# base (and the old binary) count that sample as skipped on the surface
# (add_source's d = 0); the shortcut counts it in light_samples only.
# Exit 1 while the counts differ from BASE's (or the images differ).
set -u
B=${B:-build/refray}
BASE=${BASE:-/tmp/base24/build/refray}
D=$(mktemp -d)
cat > $D/s.scene <<'EOS'
image { width 1 height 1 max_depth 2 background [1.7976931348623157e308, 1.7976931348623157e308, 1.7976931348623157e308] }
camera { orthographic eye [0, 5, 0] look_at [0, 0, 0] up [0, 0, -1] width 2 }
plane { point [0, 0, 0] normal [0, 1, 0] material { Kd 0 Ks 1 n 30 } }
sphere { center [-5, 0.5, -8] radius 0.3 material { Kd 0.5 } }
point_light { position [0, 0, 0] power 1 }
EOS
$B render $D/s.scene -q --stats -o $D/new.pfm >/dev/null 2>$D/new.st || exit 1
$BASE render $D/s.scene -q --stats -o $D/base.pfm >/dev/null 2>$D/base.st || exit 1
a=$(grep "light samples" $D/new.st) b=$(grep "light samples" $D/base.st)
echo "new: $a"; echo "base: $b"
bad=0
[ "$a" = "$b" ] || { echo "repro_on_surface: the light samples line differs"; bad=1; }
cmp -s $D/new.pfm $D/base.pfm || { echo "repro_on_surface: images differ"; bad=1; }
rm -rf $D
exit $bad
