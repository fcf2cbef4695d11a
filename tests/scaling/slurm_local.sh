#!/bin/sh
# tests/scaling/slurm_local.sh REFRAY - the Slurm recipe of spec/scaling.md
# tried for real ([SCALE-SLURM-2]): a one-node Slurm cluster (Debian
# slurm-wlm) with its own MUNGE daemon (Debian munge), all made in a
# temporary directory with a fresh key, private sockets and free ports, so
# nothing under /etc is read or changed; examples/scaling/slurm-submit.sh
# submits a job array of tiles and the merge that depends on it; the
# merged image is compared byte for byte with a render in one piece.
# Needs root (slurmd starts jobs).  `make check-slurm` runs it.
set -eu
refray=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/refray-slurm.XXXXXX")
chmod 700 "$tmp"
pids=
cleanup() {
    for p in $pids; do kill "$p" 2>/dev/null || true; done
    sleep 1
    rm -rf "$tmp"
}
trap cleanup EXIT INT TERM

# MUNGE: a key of 1024 random bytes, readable by its owner only.
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 2>/dev/null
chmod 400 "$tmp/munge.key"
/usr/sbin/munged -F --force --socket="$tmp/munge.sock" --key-file="$tmp/munge.key" \
    --log-file="$tmp/munged.log" --pid-file="$tmp/munged.pid" --seed-file="$tmp/munged.seed" 2>"$tmp/munged.err" &
pids="$pids $!"

port=$(awk 'BEGIN { srand(); print 20000 + 2 * int(rand() * 10000) }')
host=$(hostname -s)
mkdir -p "$tmp/ctld" "$tmp/slurmd" "$tmp/run"
cat > "$tmp/slurm.conf" <<CONF
ClusterName=refraytest
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge.sock
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
StateSaveLocation=$tmp/ctld
SlurmdSpoolDir=$tmp/slurmd
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(getconf _NPROCESSORS_ONLN) State=UNKNOWN
PartitionName=tiles Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$tmp/slurm.conf"
sleep 1
slurmctld -D -f "$SLURM_CONF" > "$tmp/ctld.out" 2>&1 &
pids="$pids $!"
sleep 2
slurmd -D -f "$SLURM_CONF" > "$tmp/slurmd.out" 2>&1 &
pids="$pids $!"
for i in $(seq 1 30); do
    sinfo -h -o %T 2>/dev/null | grep -q idle && break
    sleep 1
done
sinfo -h -o %T | grep -q idle || { tail "$tmp/slurmctld.log" "$tmp/slurmd.log" >&2; exit 1; }

view="--width 48 --height 30 --light-samples 8"
cp "$here/scenes/demo.scene" "$tmp/demo.scene"
# shellcheck disable=SC2086
"$refray" render -q "$tmp/demo.scene" $view -o "$tmp/whole.pfm"
ext=exr
"$refray" render -q "$tmp/demo.scene" $view --tile 0/2 -o "$tmp/probe.exr" 2>/dev/null || ext=pfm
cd "$tmp"
# shellcheck disable=SC2086
REFRAY="$refray" TILE_EXT=$ext TILES="$tmp/tiles" sh "$here/examples/scaling/slurm-submit.sh" \
    "$tmp/demo.scene" "$tmp/merged.pfm" 5 $view
for i in $(seq 1 120); do
    [ -z "$(squeue -h)" ] && break
    sleep 1
done
[ -f "$tmp/merged.pfm" ] || { cat "$tmp"/refray-*.log >&2; echo "slurm: no merged image" >&2; exit 1; }
cmp "$tmp/whole.pfm" "$tmp/merged.pfm"
[ ! -d "$tmp/tiles" ] || { echo "slurm: the merge job left the tiles" >&2; exit 1; }
echo "slurm: a job array of 5 $ext tiles and its merge job ran on a one-node Slurm: the bytes of a render in one piece"
