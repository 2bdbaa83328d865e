#!/usr/bin/env bash
# The biased-die study of docs/dice.md ("Does a dice tower make a biased die fairer?"): one
# 16 x 17.6 x 16 mm die (4 g, elasticity 0.5, friction 0.4; the y edge k = 1.1 times the others,
# so its two square faces +y and -y are the small ones) thrown THROWS times in each case:
#   floor:     by hand onto a bare floor (scenarios/dice_cube.toml's throw on the tray's felt);
#   floor_low: the tray's low toss with the tray's walls left out (a bare felt floor);
#   tray:      into the tray (scenarios/dice_two_in_tray.toml with d2 left out);
#   tower:     down the dice tower into the tray (scenarios/dice_tower.toml with d2 left out);
#   tower2:    both dice of scenarios/dice_tower.toml, both biased (one row per die).
# Writes docs/images/dice_tower_k1.1.dat (the table) and docs/images/dice_tower_k1.1.png (gnuplot).
#
#   bash tools/dice-tower-study.sh    # after building build/apps/cli/tumble; 100,000 throws a
#                                     # case, about 9 min of CPU on one thread
#   THROWS=2000 THREADS=2 OUT_DIR=/tmp TUMBLE=path/to/tumble bash tools/dice-tower-study.sh
set -euo pipefail
cd "$(dirname "$0")/.."

source tools/dice-study-common.sh
dice_study_setup dice-tower-study 100000
threads="${THREADS:-1}"
k=1.1
size="[0.016, $(awk -v k="$k" 'BEGIN { printf "%.6g", 0.016 * k }'), 0.016]"
table="$out_dir/dice_tower_k$k.dat"
plot="$out_dir/dice_tower_k$k.png"

# the scenario file FILE without the [[body]] tables named NAME... (a table ends at the next header)
without_bodies() {
    local file=$1
    shift
    awk -v names=" $* " '
        function flush() { if (buffer != "" && !drop) printf "%s", buffer; buffer = ""; drop = 0 }
        /^\[/ { flush(); if ($0 != "[[body]]") { print; next } }
        buffer != "" || $0 == "[[body]]" {
            buffer = buffer $0 "\n"
            if ($0 ~ /^name *= *"/) { name = $0; sub(/^name *= *"/, "", name); sub(/".*/, "", name)
                                      if (index(names, " " name " ")) drop = 1 }
            next
        }
        { print }
        END { flush() }' "$file"
}
without_bodies scenarios/dice_two_in_tray.toml d2 >"$work/tray.toml"
without_bodies scenarios/dice_two_in_tray.toml d2 wall_west wall_east wall_north wall_south \
    >"$work/floor_low.toml"
without_bodies scenarios/dice_tower.toml d2 >"$work/tower.toml"

# the same die in every case (both dice of tower2); on the bare floor the ground is the tray's felt
die() {
    args+=(--set "$1.size=$size" --set "$1.mass=0.004" --set "$1.elasticity=0.5"
           --set "$1.friction=0.4")
}
case_args() {
    case $1 in
        floor) args=(scenarios/dice_cube.toml --set ground.elasticity=0.3 --set ground.friction=0.6)
               die die ;;
        floor_low | tray | tower) args=("$work/$1.toml"); die d1 ;;
        tower2) args=(scenarios/dice_tower.toml); die d1; die d2 ;;
    esac
}

{
    echo "# tumble throw, dice of edges $size m, $throws throws per case, seed $seed"
    echo "# case  throws  flat  unsettled  cocked  +x -x +y -y +z -z  small  p_small  low99  high99  X2_fair  p_fair"
} >"$table"
for case in floor floor_low tray tower tower2; do
    json="$work/$case.json"
    case_args "$case"
    "$tumble" throw "${args[@]}" --throws "$throws" --seed "$seed" --threads "$threads" \
        --summary-json "$json" >"$work/$case.txt"
    grep '^time:' "$work/$case.txt" | sed "s/^/dice-tower-study: $case: /" >&2 || true
    # per die: the counts, the small faces' probability among its flat landings with its 99 %
    # Wilson interval ((D.1), z = 2.575829), and X^2 of its six faces against a fair die with its
    # p ((D.2)); a die neither flat nor in an unsettled throw was cocked
    python3 - "$case" "$json" >>"$table" <<'PYTHON'
import json, math, sys
case, path = sys.argv[1], sys.argv[2]
summary = json.load(open(path))
dice = {"die": summary["faces"]} if "faces" in summary else summary["dice"]
for die, faces in dice.items():
    name = case if len(dice) == 1 else f"{case}_{die}"
    counts = [faces[f] for f in ("+x", "-x", "+y", "-y", "+z", "-z")]
    n, small = sum(counts), faces["+y"] + faces["-y"]
    cocked = summary["throws"] - summary["unsettled"] - n
    z = 2.5758293035489004
    p, z2n = small / n, z * z / n
    centre = (p + z2n / 2) / (1 + z2n)
    half = z * math.sqrt(p * (1 - p) / n + z2n / (4 * n)) / (1 + z2n)
    x2 = sum((c - n / 6) ** 2 / (n / 6) for c in counts)
    # P(chi2_5 >= x2) = Q(5/2, y), y = x2/2: erfc(sqrt y) + exp(-y) (2 sqrt y + 4/3 y^1.5) / sqrt pi;
    # past exp's range, its log from erfc(x) ~ exp(-x^2) / (x sqrt pi) (1 - 1/(2x^2) + 3/(4x^4))
    y, root = x2 / 2, math.sqrt(x2 / 2)
    if y < 600:
        q = math.erfc(root) + math.exp(-y) * (2 * root + 4 / 3 * y * root) / math.sqrt(math.pi)
        p_fair = f"{q:.3g}"
    else:
        series = 4 / 3 * y * root + 2 * root + (1 - 1 / (2 * y) + 3 / (4 * y * y)) / root
        log10_p = (-y + math.log(series / math.sqrt(math.pi))) / math.log(10)
        exponent = math.floor(log10_p)
        p_fair = f"{10 ** (log10_p - exponent):.3g}e{exponent}"
    print(f"{name:12s} {summary['throws']:6d} {n:6d} {summary['unsettled']:4d} {cocked:4d}  "
          + " ".join(f"{c:5d}" for c in counts)
          + f"  {small:6d} {p:.5f} {centre - half:.5f} {centre + half:.5f}  {x2:9.2f} {p_fair}")
PYTHON
done

# the differences the question is about, with 99 % Wald intervals (independent throws)
python3 - "$table" >>"$table" <<'PYTHON'
import math, sys
rows = {}
for line in open(sys.argv[1]):
    if not line.startswith("#"):
        fields = line.split()
        rows[fields[0]] = (int(fields[11]), int(fields[2]))
z = 2.5758293035489004
for a, b in (("tower", "floor"), ("tower", "floor_low"), ("tower", "tray"), ("tray", "floor"),
             ("tower2_d1", "tower")):
    (ka, na), (kb, nb) = rows[a], rows[b]
    pa, pb = ka / na, kb / nb
    half = z * math.sqrt(pa * (1 - pa) / na + pb * (1 - pb) / nb)
    print(f"# p_small({a}) - p_small({b}) = {pa - pb:+.5f}, 99% interval (Wald)"
          f" [{pa - pb - half:+.5f}, {pa - pb + half:+.5f}]")
PYTHON

# the static solid-angle model for k ((D.3)): the two square faces' share of 4 pi
p_solid=$(awk -v k="$k" 'BEGIN { d = k / 2
    printf "%.5f", 2 * 4 * atan2(0.25, d * sqrt(0.5 + d * d)) / (4 * atan2(0, -1)) }')
echo "# solid-angle model: p_small = $p_solid; fair die: 1/3" >>"$table"

gnuplot <<GNUPLOT
set terminal pngcairo size 900,560 font ",11" noenhanced
set output "$plot"
set title "A 16 x 17.6 x 16 mm die (k = $k): probability of landing on one of its two small faces"
set ylabel "P(small face down)"
set key below
set grid ytics
set xrange [-0.5:5.5]
plot "$table" using 0:13:14:15:xticlabels(1) with yerrorbars pt 7 ps 1.3 lc rgb "#d62728" title "tumble throw ($throws throws per case, 99% Wilson)", \
     1.0 / 3.0 with lines dt 2 lw 2 lc rgb "#7f7f7f" title "1/3 (fair die)", \
     $p_solid with lines lw 2 lc rgb "#1f77b4" title "static solid-angle model ($p_solid)"
GNUPLOT
echo "dice-tower-study: wrote $table and $plot" >&2
cat "$table"
