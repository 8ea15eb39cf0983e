#!/bin/sh
# Markdown tables from bench/results (bench/run-all.sh): per measurement set
# and configuration, the median over the runs of the run's median frame time
# and of its ratio to the run's base configuration; counts, fragments and
# errors are the same in every run and come from run 1.
#   bench/summarise.sh RESULTS_DIR > summary.md
set -eu
dir=${1:?usage: summarise.sh RESULTS_DIR}
for first in "$dir"/*.1.csv; do
    set_name=$(basename "$first" .1.csv)
    echo "### $set_name"
    echo
    echo "| config | frame ms (median of runs) | per run | vs base | submit ms | frag/px | draws | portal passes drawn | culled | id mismatch % | PSNR dB |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|"
    for f in "$dir/$set_name".*.csv; do
        run=$(basename "$f" .csv)
        run=${run##*.}
        tail -n +2 "$f" | sed "s/^/$run,/"
    done | awk -F, '
        function median(list,   n, a, i, j, t) {
            n = split(list, a, " ")
            for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] + 0 > a[j] + 0; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
            return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
        }
        # fields: run,name,group,w,h,depth,median,p10,p90,vs_base,submit,frag,draws,tris,drawn,culled,fills,mism,psnr
        {
            name = $2
            if (!(name in seen)) { seen[name] = 1; order[++count] = name }
            ms[name] = ms[name] " " $7
            ratio[name] = ratio[name] " " $10
            submit[name] = submit[name] " " $11
            if ($1 == 1) { frag[name] = $12; draws[name] = $13; drawn[name] = $15; culled[name] = $16; mism[name] = $18; psnr[name] = $19 }
        }
        END {
            for (i = 1; i <= count; i++) {
                n = order[i]
                printf "| %s | %.3f | %s | %.3f | %.3f | %s | %s | %s | %s | %s | %s |\n", n, median(ms[n]), substr(ms[n], 2),
                       median(ratio[n]), median(submit[n]), frag[n], draws[n], drawn[n], culled[n],
                       mism[n] == "" ? "-" : mism[n], psnr[n] == "" ? "-" : psnr[n]
            }
        }'
    echo
done
