#!/usr/bin/env bash
# The dice study of docs/dice.md: for square cuboid dice (x and z edges 2 cm, y edge k times
# that, k = 0.5 .. 2.5) throw each THROWS times with `tumble throw` and compare the probability
# of landing on one of the two square faces (+y or -y) with the static solid-angle model.
# Writes docs/images/dice_k.dat (the table) and docs/images/dice_k.png (the plot, gnuplot).
#
#   bash tools/dice-study.sh            # after building build/apps/cli/tumble
#   THROWS=500 OUT_DIR=/tmp TUMBLE=path/to/tumble bash tools/dice-study.sh
set -euo pipefail
cd "$(dirname "$0")/.."

source tools/dice-study-common.sh
dice_study_setup dice-study 10000
edge=0.02
table="$out_dir/dice_k.dat"
plot="$out_dir/dice_k.png"

# one JSON value by key: "+y": 123 -> 123
json_count() { grep -o "\"$2\": [0-9]*" "$1" | head -n1 | sed 's/.*: //'; }

{
    echo "# tumble throw scenarios/dice_cube.toml with size = [$edge, k*$edge, $edge], $throws throws per k, seed $seed"
    echo "# k  settled  square  p_square  wilson_low  wilson_high  p_solid_angle"
} >"$table"
for k in 0.5 0.75 1.0 1.25 1.5 1.75 2.0 2.25 2.5; do
    height=$(awk -v k="$k" -v e="$edge" 'BEGIN { printf "%.17g", k * e }')
    json="$work/k$k.json"
    "$tumble" throw scenarios/dice_cube.toml --throws "$throws" --seed "$seed" \
        --set "die.size=[$edge, $height, $edge]" --summary-json "$json" >/dev/null
    plus=$(json_count "$json" "+y")
    minus=$(json_count "$json" "-y")
    unsettled=$(json_count "$json" "unsettled")
    # p of a square face among settled throws, its 95% Wilson interval (docs/dice.md, (D.1)),
    # and the solid angle the two square faces subtend from the centre over 4 pi ((D.3))
    awk -v k="$k" -v n="$throws" -v u="$unsettled" -v s="$((plus + minus))" 'BEGIN {
        z = 1.959963984540054; m = n - u; p = s / m; z2n = z * z / m
        c = (p + z2n / 2) / (1 + z2n); h = z * sqrt(p * (1 - p) / m + z2n / (4 * m)) / (1 + z2n)
        pi = atan2(0, -1); a = 0.5; b = 0.5; d = k / 2
        omega = 4 * atan2(a * b, d * sqrt(a * a + b * b + d * d))
        printf "%-5s %-8d %-7d %.6f  %.6f    %.6f     %.6f\n", k, m, s, p, c - h, c + h, 2 * omega / (4 * pi)
    }' >>"$table"
    echo "dice-study: k = $k done" >&2
done

gnuplot <<GNUPLOT
set terminal pngcairo size 900,560 font ",11" noenhanced
set output "$plot"
set title "Square cuboid dice (edges 1 x k x 1): probability of landing on a square face"
set xlabel "k (long edge / square edge)"
set ylabel "P(square face down)"
set key top right
set grid
set xrange [0.4:2.6]
set yrange [0:1]
# (D.3): the two square faces subtend 2 * 4 atan(1/4 / (d sqrt(1/2 + d^2))), d = k/2, of 4 pi
solid(k) = 2 * atan((0.25) / ((k / 2) * sqrt(0.5 + (k / 2) ** 2))) / pi
plot "$table" using 1:4:5:6 with yerrorbars pt 7 lc rgb "#d62728" title "tumble throw ($throws throws per k, 95% Wilson)", \
     solid(x) with lines lw 2 lc rgb "#1f77b4" title "static solid-angle model", \
     1.0 / 3.0 with lines dt 2 lc rgb "#7f7f7f" title "1/3 (cube)"
GNUPLOT
echo "dice-study: wrote $table and $plot"
cat "$table"
