#!/bin/sh
# The `fresnel eval` contract: every model, both types, bad input.
F="$BUILD/fresnel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
printf 'eta,kappa,cos\n# gold red, glass, water from glass\n0.17,3.5,1\n1.5,0,1\n1.5,0,0\n\n0.2,3.5,0.5\n' >"$t/in"
for m in schlick schlick-gen lsk lsk-comp f82 gulbrandsen cook-torrance exact approx-conductor schlick-internal; do
    for ty in f32 f64; do
        if "$F" eval --model "$m" --type "$ty" <"$t/in" >"$t/out" 2>"$t/err" && [ "$(wc -l <"$t/out")" -eq 4 ] &&
            ! grep -qiE 'nan|inf' "$t/out"; then
            echo "PASS eval --model $m --type $ty: 4 lines"
        else
            echo "FAIL eval --model $m --type $ty: $(cat "$t/err") $(cat "$t/out" | tr '\n' ' ')"
        fi
    done
done
# glass F0 = 0.04: 9 significant digits for f32, 17 for f64, each within its precision
v=$(printf '1.5,0,1\n' | "$F" eval --model exact --type f32)
printf '%s\n' "$v" | grep -qE '^0\.0[0-9]{9}$' && awk -v v="$v" 'BEGIN { d = v - 0.04; exit !(d < 3e-7 && d > -3e-7) }' &&
    echo "PASS eval f32 prints %.9g (glass F0 $v)" || echo "FAIL eval f32 glass F0: '$v'"
v=$(printf '1.5,0,1\n' | "$F" eval --model exact --type f64)
printf '%s\n' "$v" | grep -qE '^0\.0[0-9]{17}$' && awk -v v="$v" 'BEGIN { d = v - 0.04; exit !(d < 1e-16 && d > -1e-16) }' &&
    echo "PASS eval f64 prints %.17g ($v)" || echo "FAIL eval f64 glass F0: '$v'"
# glass to air (n1 1.5, eta 1): total internal reflection past c = sqrt(1 - 1/1.5^2) = 0.745
v=$(printf '1,0,0.7\n1,0,0.9\n' | "$F" eval --model exact --type f64 --n1 1.5 | tr '\n' ' ')
case "$v" in "1 0."*) echo "PASS eval --n1 1.5: TIR at c 0.7, partial at c 0.9 ($v)" ;; *) echo "FAIL eval --n1: '$v'" ;; esac
expect_error() { # name, expected stderr pattern, args..., stdin in $t/bad
    name=$1; pat=$2; shift 2
    "$F" "$@" <"$t/bad" >"$t/out" 2>"$t/err"
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qE -e "$pat" "$t/err" && [ ! -s "$t/out" ]; then
        echo "PASS $name (exit 2: $(head -1 "$t/err"))"
    else
        echo "FAIL $name: exit $rc, stderr '$(cat "$t/err")', stdout '$(head -2 "$t/out")'"
    fi
}
printf '1.5,0,1\n1.5,abc,0.5\n' >"$t/bad"
expect_error "non-numeric field names line and column" '^<stdin>:2:2: .*kappa' eval --model exact --type f32
printf '1.5,0,1\n1.5,0\n' >"$t/bad"
expect_error "missing column names the line" '^<stdin>:2: expected 3 columns' eval --model exact --type f32
printf '1.5,0,1,4\n' >"$t/bad"
expect_error "extra column names the line" '^<stdin>:1: expected 3 columns' eval --model exact --type f32
printf '1.5,0,nan\n' >"$t/bad"
expect_error "non-finite field" '^<stdin>:1:3: ' eval --model exact --type f32
printf '' >"$t/bad"
expect_error "unknown model" "unknown model 'fresnel'" eval --model fresnel --type f32
expect_error "unknown type" "unknown type 'f16x'" eval --model exact --type f16x
expect_error "missing --model" "--model is required" eval --type f32
expect_error "unknown command" "unknown command" frobnicate
if "$F" --help | grep -q eval && "$F" eval --help | grep -q 'schlick-internal'; then
    echo "PASS fresnel --help and fresnel eval --help describe the command and models"
else
    echo "FAIL --help output"
fi
