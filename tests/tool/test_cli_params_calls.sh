#!/bin/sh
# passes: first (the tool's output does not depend on the pass)
# `fresnel params` says which rows each runtime call takes: a line per scene
# model with its _rgb call, every argument but c one of the CSV's rows; the
# exact conductor on the fitted eta, kappa, and the Gaussian-window and
# point-sampled sets on their own calls. And those are the constants the
# header of a scene with those models holds under the model's call: the
# header's eta, kappa, eta_gaussian and kappa_gaussian are the rows named.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
if ! "$F" params --material cu >"$t/p" 2>"$t/err"; then
    echo "FAIL params --material cu: $(head -2 "$t/err")"
    exit 0
fi
rows=$(sed -n 's/^\([a-z_0-9]*\),.*/\1/p' "$t/p")
bad=""
n=0
for args in $(sed -n 's/^#   [a-z0-9-]* *fresnel_[a-z_]*(\(.*\))$/\1/p' "$t/p" | tr -d ' '); do
    n=$((n + 1))
    for a in $(echo "$args" | tr ',' ' '); do
        [ "$a" = c ] || echo "$rows" | grep -qx "$a" || bad="$bad $a"
    done
done
if [ "$n" -ge 9 ] && [ -z "$bad" ]; then
    echo "PASS params names the rows of each of $n scene models' runtime calls, every one a row it prints"
else
    echo "FAIL params' call lines: $n lines, arguments that are not rows:$bad"
fi
missing=""
for m in "exact fresnel_conductor_rgb(eta_fit, kappa_fit, c)" "exact-gaussian fresnel_conductor_rgb(eta_gaussian, kappa_gaussian, c)" \
    "exact-point fresnel_conductor_rgb(eta_point, kappa_point, c)" "f82 fresnel_f82_rgb(f0, f82, c)"; do
    sed -n "s/^#   $(echo "$m" | cut -d' ' -f1)  *//p" "$t/p" | grep -qxF "$(echo "$m" | cut -d' ' -f2-)" ||
        missing="$missing [$m]"
done
[ -z "$missing" ] && echo "PASS params: the exact conductor takes eta_fit, kappa_fit; the Gaussian-window and point-sampled sets their own calls" ||
    echo "FAIL params' call lines lack:$missing"
# the header's constants under those names are the rows' numbers (binary32)
printf 'materials = cu\nmodels = exact exact-gaussian\n' >"$t/e.scene"
if "$F" gen "$t/e.scene" -o "$t/e.h" 2>"$t/err"; then
    off=""
    for pair in eta:eta_fit kappa:kappa_fit eta_gaussian:eta_gaussian kappa_gaussian:kappa_gaussian; do
        h=$(sed -n "s/^static const fresnel_rgb fresnel_e_cu_${pair%%:*} [A-Z_]* = {\(.*\)};/\1/p" "$t/e.h" | tr -d 'f ')
        r=$(sed -n "s/^${pair#*:},//p" "$t/p")
        awk -v h="$h" -v r="$r" 'BEGIN { n = split(h, a, ","); split(r, b, ",");
            for (i = 1; i <= 3; i++) { d = a[i] - b[i]; if (d < 0) d = -d; if (n != 3 || d > 1e-6 * (b[i] < 0 ? -b[i] : b[i]) + 1e-30) exit 1 } }' ||
            off="$off ${pair%%:*}=[$h] ${pair#*:}=[$r]"
    done
    [ -z "$off" ] && echo "PASS params: the header's eta, kappa, eta_gaussian, kappa_gaussian are the rows eta_fit, kappa_fit, eta_gaussian, kappa_gaussian" ||
        echo "FAIL params rows against the header's constants:$off"
else
    echo "FAIL gen e.scene: $(head -2 "$t/err")"
fi
