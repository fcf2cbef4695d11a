#!/bin/sh
# examples/scaling/slurm-submit.sh SCENE OUT N [RENDER OPTION...]
#
# Submits SCENE as a Slurm job array of N tiles (slurm-tiles.sbatch, next
# to this script) and a merge job that runs once every tile succeeded
# (--dependency=afterok), writing OUT (spec/scaling.md).  The scene, OUT
# and the tile directory (TILES, default ./refray-tiles.PID) must be on a
# file system every node sees.  SBATCH_OPTS goes to both sbatch calls (a
# partition, an account; --cpus-per-task=C for tiles on C processors
# each).  REFRAY and TILE_EXT as in slurm-tiles.sbatch.  Prints the job ids.
set -eu

if [ $# -lt 3 ]; then
    echo "usage: slurm-submit.sh SCENE OUT N [RENDER OPTION...]" >&2
    exit 64
fi
scene=$1 out=$2 n=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
refray=${REFRAY:-refray}
ext=${TILE_EXT:-exr}
tiles=${TILES:-$(pwd)/refray-tiles.$$}
mkdir -p "$tiles"
# shellcheck disable=SC2086
array=$(sbatch --parsable ${SBATCH_OPTS:-} --array=0-$((n - 1)) --export=ALL,REFRAY="$refray",TILE_EXT="$ext" \
    "$here/slurm-tiles.sbatch" "$scene" "$tiles" "$@")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable ${SBATCH_OPTS:-} --job-name=refray-merge --dependency=afterok:"$array" \
    --output=refray-merge-%j.log \
    --wrap "'$refray' merge '$tiles'/tile-*.$ext -o '$out' && rm -rf '$tiles'")
echo "tiles: job array $array ($n tasks); merge: job ${merge%%;*}, writes $out"
