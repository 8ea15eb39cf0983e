#!/bin/sh
# Plots of bench/results (bench/run-all.sh) with gnuplot, as SVG:
#   frame_vs_portals.svg   frame time against open doors (VR-study layout)
#   frame_vs_size.svg      frame time against pixels per eye
#   frame_vs_depth.svg     frame time against recursion depth, open corridor and behind a wall
#   speed_vs_error.svg     frame time (relative to the default technique) against id mismatch
# Installs Debian's gnuplot-nox when gnuplot is missing (never from a test).
set -eu
dir=${1:?usage: plot.sh RESULTS_DIR}
if ! command -v gnuplot >/dev/null 2>&1; then
    echo "plot.sh: installing gnuplot-nox" >&2
    apt-get install -y gnuplot-nox >/dev/null || { echo "plot.sh: need gnuplot (apt-get install gnuplot-nox)" >&2; exit 1; }
fi

# dat SET GROUP: "x median_ms" per configuration of GROUP, x the value after '=', median over runs.
dat() {
    cat "$dir/$1".*.csv | awk -F, -v g="$2" '
        function median(list,   n, a, i, j, t) {
            n = split(list, a, " ")
            for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] + 0 > a[j] + 0; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
            return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
        }
        $2 == g { x = substr($1, index($1, "=") + 1); if (g == "size") { split(x, s, "x"); x = s[1] * s[2] }
                  if (!(x in v)) order[++n] = x; v[x] = v[x] " " $6 }
        END { for (i = 1; i <= n; i++) print order[i], median(v[order[i]]) }'
}
dat portals_vr portals >"$dir/portals.dat"
dat size_vr size >"$dir/size.dat"
dat depth_wall depth >"$dir/depth_wall.dat"
dat depth_wall_occlusion depth >"$dir/depth_wall_occlusion.dat"
dat depth_open depth >"$dir/depth_open.dat"
# name vs_base id_mismatch, from run 1 of the technique sets (mismatch is deterministic).
for s in corridor vr; do
    awk -F, 'NR > 1 && $17 != "" { print $1, $9, $17 }' "$dir/techniques_$s.1.csv" >"$dir/speed_error_$s.dat"
done

gnuplot <<GP
set terminal svg size 640,400 dynamic
set grid
set key top left
set output "$dir/frame_vs_portals.svg"
set title "VR-study layout, 1280x720 per eye, depth 4"
set xlabel "open portals"; set ylabel "frame ms (median)"
set xtics 2
plot "$dir/portals.dat" using 1:2 with linespoints pt 7 title "frame time"
set output "$dir/frame_vs_size.svg"
set title "VR-study layout, six portals, depth 4"
set xlabel "pixels per eye"; set ylabel "frame ms (median)"
set xtics auto
plot "$dir/size.dat" using 1:2 with linespoints pt 7 title "frame time"
set output "$dir/frame_vs_depth.svg"
set title "Endless corridor, 1280x720 per eye"
set xlabel "max depth"; set ylabel "frame ms (median)"
set logscale x 2
plot "$dir/depth_open.dat" using 1:2 with linespoints pt 7 title "open", \
     "$dir/depth_wall.dat" using 1:2 with linespoints pt 5 title "behind a wall", \
     "$dir/depth_wall_occlusion.dat" using 1:2 with linespoints pt 9 title "behind a wall, --occlusion-test"
unset logscale x
set output "$dir/speed_vs_error.svg"
set title "Speed against error (640x360 per eye; error against the tracer at depth 64)"
set xlabel "frame time / default technique"; set ylabel "cell-id mismatch %"
plot "$dir/speed_error_corridor.dat" using 2:3 with points pt 7 title "corridor", \
     "" using 2:3:1 with labels offset 0,0.7 font ",7" notitle, \
     "$dir/speed_error_vr.dat" using 2:3 with points pt 5 title "VR study", \
     "" using 2:3:1 with labels offset 0,-0.7 font ",7" notitle
GP
