# lights.sh - sourced by hand_hidden.sh and dbl_campaign.sh: hidden_light
# KIND POWER sets l to the light of that kind (point, pointlin, pointinv,
# pointd0, disk, tiny, rect, distant) over the floor of their scenes.
hidden_light() {
    p=$2
    case $1 in
    point) l="point_light { position [0.3, 1, -0.5] power $p falloff none }" ;;
    pointlin) l="point_light { position [0.3, 1, -0.5] power $p d0 0 falloff linear }" ;;
    pointinv) l="point_light { position [0.3, 0.2, -0.5] power $p d0 0 falloff inverse_square }" ;;
    pointd0) l="point_light { position [0.3, 0.01, -0.5] power $p d0 1 falloff inverse_square }" ;;
    disk) l="distributed_light { disk [0, 0.01, -0.5] [0, -1, 0] 1 power $p samples 16 falloff inverse_square }" ;;
    tiny) l="distributed_light { disk [0.2, 1, -0.5] [0, -1, 0] 0.001 power $p samples 64 }" ;;
    rect) l="distributed_light { rectangle [-2, 0.02, -0.5] [4, 0, 0] [0, 0, 0.001] power $p samples 16 falloff inverse_square }" ;;
    distant) l="distant_light { direction [0, -0.2, 1] power $p }" ;;
    esac
}
