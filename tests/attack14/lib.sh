# lib.sh - sourced by the mesh scripts of tests/attack14 (run from the
# repository root): R the binary, A this directory, D a temporary
# directory removed at exit, and
#   mesh_scene TEMPLATE NAME   $D/NAME.scene from $A/TEMPLATE with MESH
#                              replaced by NAME.obj, the mesh copied beside it
set -u
R=${REFRAY:-build/refray}
A=tests/attack14
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
mesh_scene() {
    cp "$A/$2.obj" "$D/" && sed "s/MESH/$2.obj/" "$A/$1" > "$D/$2.scene"
}
