#!/bin/sh
# tests/scaling/ssh_localhost.sh REFRAY - the --sshlogin recipe of
# spec/scaling.md tried for real, against this machine ([SCALE-SSH-1]):
# a private sshd (Debian openssh-server) on a free port of 127.0.0.1, with
# its own host key and one key pair made here for the current user, all in
# a temporary directory removed at the end; nothing in ~/.ssh or /etc/ssh
# is read or changed.  GNU parallel logs in through it (rsync moves the
# scene there and the tiles back), then the tiles are merged and compared
# byte for byte with a render in one piece.  `make check-ssh` runs it.
set -eu
refray=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/refray-ssh.XXXXXX")
sshd_pid=
cleanup() {
    [ -z "$sshd_pid" ] || kill "$sshd_pid" 2>/dev/null || true
    rm -rf "$tmp"
}
trap cleanup EXIT INT TERM

ssh-keygen -q -t ed25519 -N '' -f "$tmp/host_key"
ssh-keygen -q -t ed25519 -N '' -f "$tmp/user_key"
cp "$tmp/user_key.pub" "$tmp/authorized_keys"
chmod 600 "$tmp/authorized_keys"
# A port nobody listens on, from the dynamic range.
port=$(awk 'BEGIN { srand(); print 20000 + int(rand() * 20000) }')
cat > "$tmp/sshd_config" <<CONF
Port $port
ListenAddress 127.0.0.1
HostKey $tmp/host_key
AuthorizedKeysFile $tmp/authorized_keys
PidFile $tmp/sshd.pid
StrictModes no
PermitRootLogin prohibit-password
PasswordAuthentication no
KbdInteractiveAuthentication no
UsePAM no
Subsystem sftp internal-sftp
CONF
# sshd's privilege separation directory (Debian creates it at boot).
[ -d /run/sshd ] || mkdir -p /run/sshd
/usr/sbin/sshd -f "$tmp/sshd_config" -D -e 2> "$tmp/sshd.log" &
sshd_pid=$!
ssh="ssh -p $port -i $tmp/user_key -o BatchMode=yes -o StrictHostKeyChecking=no -o UserKnownHostsFile=/dev/null -o LogLevel=ERROR"
for i in 1 2 3 4 5 6 7 8 9 10; do
    $ssh "$(id -un)@127.0.0.1" true 2>/dev/null && break
    sleep 0.5
done
$ssh "$(id -un)@127.0.0.1" true || { cat "$tmp/sshd.log" >&2; exit 1; }

ext=exr
"$refray" render -q "$here/scenes/demo.scene" --width 48 --height 30 --light-samples 8 --tile 0/1 \
    -o "$tmp/probe.exr" 2>/dev/null || ext=pfm
view="--width 48 --height 30 --light-samples 8"
# shellcheck disable=SC2086
"$refray" render -q "$here/scenes/demo.scene" $view -o "$tmp/whole.pfm"
# shellcheck disable=SC2086
SSH="$ssh" SSHLOGIN="2/$(id -un)@127.0.0.1" REFRAY="$refray" TILE_EXT=$ext TILES="$tmp/refray-tiles.$$" \
    sh "$here/examples/scaling/parallel-tiles.sh" "$here/scenes/demo.scene" "$tmp/merged.pfm" 6 $view
cmp "$tmp/whole.pfm" "$tmp/merged.pfm"
n=$(ls "$tmp/refray-tiles.$$" | grep -c "^tile-.*\.$ext\$")
[ "$n" = 6 ] || { echo "ssh: $n tiles came back, not 6" >&2; exit 1; }
echo "ssh: 6 $ext tiles rendered through ssh to $(id -un)@127.0.0.1:$port and merged: the bytes of a render in one piece"
