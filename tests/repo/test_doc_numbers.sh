#!/bin/sh
# passes: first (text against text)
# One number per claim: the figures the public headers and READMEs quote
# from a measurement are that measurement's, data/report/report.md (written
# by `make report`): the thin film's CIEDE2000 (binary32, Q1.15, binary16,
# mean and max), its binary32 time, its tables' bytes and its Cortex-M0
# instructions, wherever they are quoted (include/fresnel_film.h, README.md,
# tests/README.md's pole table, its six-pole row being the shipped film);
# and the LUTs' Cortex-M0 counts fresnel_q15.h quotes.
R=data/report/report.md
film=$(sed -n '/^## Thin film/,/^## /p' "$R")
all=$(echo "$film" | grep -m1 '^| all | |' | awk -F'|' '{ gsub(/ /, ""); print $4, $5, $6, $7, $8, $9 }')
m0=$(echo "$film" | sed -n 's/^Cortex-M0 (`make cross-count`): \([0-9]*\) instructions per RGB evaluation of fresnel_film_q15_rgb\.$/\1/p')
bytes=$(echo "$film" | awk -F'|' '/^\| (f32|q15|f16) \| [0-9]+ \|/ { gsub(/ /, "", $3); printf "%s ", $3 }')
ns=$(echo "$film" | awk -F'|' '/^\| f32 \| [0-9]+ \|/ { gsub(/ /, "", $4); print $4 }')
if [ -z "$all" ] || [ -z "$m0" ] || [ -z "$ns" ] || [ "$(echo $bytes | wc -w)" -ne 3 ]; then
    echo "FAIL doc numbers: $R's thin-film section lacks its all row, M0 count, table bytes or time ($all / $m0 / $bytes / $ns)"
    exit 0
fi
H=include/fresnel_film.h
# the header's accuracy table: binary32, Q1.15, binary16 mean and max
hdr=$(awk '/^ \*     binary32 /{ b = $3 " " $4 } /^ \*     Q1.15 /{ q = $3 " " $4 } /^ \*     binary16 /{ h = $3 " " $4 }
    END { print b, q, h }' "$H")
[ "$hdr" = "$all" ] && echo "PASS $H's CIEDE2000 table (mean, max per type: $hdr) is $R's thin-film row all" ||
    echo "FAIL $H's CIEDE2000 table '$hdr' is not $R's thin-film row all '$all'"
hns=$(sed -n 's/.*Measured: \([0-9.]*\) ns (gcc.*/\1/p' "$H")
[ "$hns" = "$ns" ] && echo "PASS $H's binary32 time ($hns ns) is $R's" ||
    echo "FAIL $H's binary32 time '$hns' ns is not $R's '$ns'"
hb=$(tr '\n' ' ' <"$H" | sed -n 's/.*sizeof(fresnel_film) \([0-9]*\) bytes, fresnel_film_q15 *\** *\([0-9]*\), fresnel_film_f16 \([0-9]*\) .*/\1 \2 \3 /p')
[ "$hb" = "$bytes" ] && echo "PASS $H's table bytes per material ($hb) are $R's" ||
    echo "FAIL $H's table bytes '$hb' are not $R's '$bytes'"
# the Cortex-M0 count, in every text that quotes it
bad=""
grep -q "Measured: $m0 instructions" "$H" || bad="$bad $H"
grep '^| a thin film' README.md | grep -q " $m0 Cortex-M0 instructions" || bad="$bad README.md"
[ "$(awk -F'|' '$2 ~ /^ 6 $/ { gsub(/ /, "", $7); print $7 }' tests/README.md)" = "$m0" ] || bad="$bad tests/README.md(poles 6)"
[ -z "$bad" ] && echo "PASS the film's Cortex-M0 count ($m0) is $R's in $H, README.md and tests/README.md's six-pole row" ||
    echo "FAIL the film's Cortex-M0 count is not $R's $m0 in:$bad"
# fresnel_q15.h's LUT counts: the Cortex-M0 means of the rows it names
m0mean() { sed -n '/^== m0 fixed point/,/^== /p' "$R" | awk -v r="$1" 'index($0, r " ") == 1 {
    rest = substr($0, length(r) + 1); split(rest, v, " "); if (v[1] ~ /^[0-9]+$/) { print v[1]; exit } }'; }
Q=include/fresnel_q15.h
q=$(tr '\n' ' ' <"$Q" | sed 's/ \* / /g')
u16=$(m0mean "lut u16") lin=$(m0mean "lut-linear u16") cub=$(m0mean "lut-cubic u16")
bad=""
echo "$q" | grep -q "): $u16 instructions per call (_u16), $lin uniform in c\." || bad="$bad lut-u16=$u16/lut-linear=$lin"
echo "$q" | grep -q "per channel; $cub Cortex-M0 instructions per call" || bad="$bad lut-cubic=$cub"
[ -n "$u16" ] && [ -z "$bad" ] && echo "PASS $Q's LUT instruction counts ($u16, $lin, $cub) are $R's Cortex-M0 means" ||
    echo "FAIL $Q's LUT instruction counts are not $R's:$bad"
