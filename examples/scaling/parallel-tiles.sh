#!/bin/sh
# examples/scaling/parallel-tiles.sh SCENE OUT N [RENDER OPTION...]
#
# Renders SCENE as N tiles with GNU parallel (Debian: parallel), one
# single-threaded refray process per tile, then merges them into OUT
# (spec/scaling.md).  The tiles are bit for bit the pixels of a render in
# one piece, so OUT is the file `refray render SCENE -o OUT` writes.
#
# Environment:
#   REFRAY     the refray program (default: refray, on every machine)
#   SSHLOGIN   GNU parallel's --sshlogin value, e.g. "4/alice@node1,8/node2"
#              ("N/" caps the tiles a machine renders at once; ":" is this
#              machine): each machine receives the scene (--basefile) and
#              sends its tiles back (--return); it needs refray on its PATH
#              (or REFRAY as a path valid there) and ssh without a password
#   SSH        the ssh command GNU parallel uses (default: ssh)
#   TILE_EXT   exr (default) or pfm (a build without OpenEXR)
#   TILES      where the tiles go (default: a new directory under TMPDIR,
#              removed after the merge)
# A scene that includes other files or meshes needs them on every machine:
# give them with more --basefile options in PARALLEL_OPTS, or a shared
# file system.  PARALLEL_OPTS is passed to GNU parallel as it is.
set -eu

if [ $# -lt 3 ]; then
    echo "usage: parallel-tiles.sh SCENE OUT N [RENDER OPTION...]" >&2
    exit 64
fi
scene=$1 out=$2 n=$3
shift 3
refray=${REFRAY:-refray}
ext=${TILE_EXT:-exr}
own_tiles=0
if [ -z "${TILES:-}" ]; then
    TILES=$(mktemp -d "${TMPDIR:-/tmp}/refray-tiles.XXXXXX")
    own_tiles=1
fi
mkdir -p "$TILES"

if [ -z "${SSHLOGIN:-}" ]; then
    # -q: each word passes as it is (a path may hold spaces).
    # shellcheck disable=SC2086
    seq 0 $((n - 1)) | parallel --will-cite -q --halt now,fail=1 ${PARALLEL_OPTS:-} \
        "$refray" render -q "$scene" --tile "{}/$n" -o "$TILES/tile-{}.$ext" "$@"
else
    # Remote machines: the scene goes as a base file and the tiles come
    # back, all named relative to the tile directory here and to a
    # directory of the same name under REMOTE_DIR (default /tmp) there,
    # whose files --cleanup removes.
    cp "$scene" "$TILES/scene.scene"
    returns="--return tile-{}.$ext"
    [ "$ext" = pfm ] && returns="$returns --return tile-{}.$ext.tile"
    # shellcheck disable=SC2086
    (cd "$TILES" && seq 0 $((n - 1)) | parallel --will-cite -q --halt now,fail=1 --ssh "${SSH:-ssh}" \
        --sshlogin "$SSHLOGIN" --workdir "${REMOTE_DIR:-/tmp}/$(basename "$TILES")" --basefile scene.scene $returns --cleanup ${PARALLEL_OPTS:-} \
        "$refray" render -q scene.scene --tile "{}/$n" -o "tile-{}.$ext" "$@")
    rm -f "$TILES/scene.scene"
fi
"$refray" merge "$TILES"/tile-*."$ext" -o "$out"
[ "$own_tiles" = 0 ] || rm -rf "$TILES"
