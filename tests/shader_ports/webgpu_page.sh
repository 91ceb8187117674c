#!/bin/sh
# WebGPU pages in a headless browser, for the tests that run WGSL
# (tests/shader_ports/test_wgsl.sh, tests/repo/test_readme.sh):
#   sh tests/shader_ports/webgpu_page.sh run PAGE.html LOG [chromium|firefox]
#       opens PAGE in headless Chromium (Tint on SwiftShader) or Firefox ESR
#       (naga on lavapipe) and waits, at most WGSL_TIMEOUT seconds (240),
#       for the page's WGSL_DONE line in LOG (Chromium's stderr, Firefox's
#       stdout: a page logs through console.log and dump()); the browser is
#       stopped either way. Exit 0 when the line came.
#   sh tests/shader_ports/webgpu_page.sh compile MODULE.wgsl DIR [browser]
#       a page in DIR that compiles MODULE (no entry point needed; a module
#       that starts with `enable f16;` on a device with shader-f16) and
#       prints the compiler's messages from getCompilationInfo() with their
#       line numbers; exit 0 when it compiled without an error.
# Run from the top of the tree; CHROMIUM names Chromium's command.
timeout_s=${WGSL_TIMEOUT:-240}

run_page() { # page log browser
    dir=$(dirname "$2")/profile.$$
    rm -rf "$dir"
    mkdir -p "$dir"
    case $1 in /*) url=file://$1 ;; *) url=file://$(pwd)/$1 ;; esac
    if [ "$3" = firefox ]; then
        # WebGPU on (lavapipe, naga) and dump() to stdout
        printf 'user_pref("%s", true);\n' dom.webgpu.enabled gfx.webgpu.force-enabled gfx.webgpu.ignore-blocklist \
            browser.dom.window.dump.enabled >"$dir/user.js"
        case $dir in /*) ;; *) dir=$(pwd)/$dir ;; esac
        HOME="$dir" firefox-esr --headless --no-remote --profile "$dir" "$url" >"$2" 2>&1 &
    else
        HOME="$dir" "${CHROMIUM:-chromium}" --headless=new --no-sandbox --enable-unsafe-webgpu \
            --use-webgpu-adapter=swiftshader --user-data-dir="$dir" --enable-logging=stderr --v=0 "$url" \
            >/dev/null 2>"$2" &
    fi
    pid=$!
    waited=0
    while ! grep -aq 'WGSL_DONE' "$2" 2>/dev/null; do
        if ! kill -0 $pid 2>/dev/null || [ $waited -ge "$timeout_s" ]; then
            break
        fi
        sleep 1
        waited=$((waited + 1))
    done
    kill $pid 2>/dev/null
    wait $pid 2>/dev/null
    rm -rf "$dir"
    grep -aq 'WGSL_DONE' "$2"
}

case ${1-} in
run)
    run_page "$2" "$3" "${4:-chromium}"
    ;;
compile)
    b=${4:-chromium}
    page=$3/compile_$b.html
    {
        echo '<!DOCTYPE html><html><body><script type="text/wgsl" id="wgsl">'
        cat "$2"
        echo '</script><script>'
        echo 'const log = (s) => { console.log(s); if (typeof dump === "function") dump(s + String.fromCharCode(10)); };'
        echo '(async () => { try { const code = document.getElementById("wgsl").textContent;'
        echo '  const f16 = /^enable f16;/m.test(code), a = await navigator.gpu.requestAdapter();'
        echo '  if (f16 && !a.features.has("shader-f16")) { log("WGSL_DONE error: no shader-f16 here"); return; }'
        echo '  const d = await a.requestDevice(f16 ? {requiredFeatures: ["shader-f16"]} : {});'
        echo '  const m = d.createShaderModule({code});'
        echo '  const info = await m.getCompilationInfo(); let bad = 0;'
        echo '  for (const x of info.messages) { log("WGSL " + x.type + " line " + x.lineNum + ": " + x.message);'
        echo '    if (x.type === "error") bad = 1; }'
        echo '  log(bad ? "WGSL_DONE error" : "WGSL_DONE ok"); } catch (e) { log("WGSL_DONE error " + e); } })();'
        echo '</script></body></html>'
    } >"$page"
    run_page "$page" "$3/compile_$b.log" "$b"
    grep -ao 'WGSL [a-z]* line [^"]*' "$3/compile_$b.log" | head -5
    grep -aq 'WGSL_DONE ok' "$3/compile_$b.log"
    ;;
*)
    echo "usage: webgpu_page.sh run PAGE LOG [chromium|firefox] | compile MODULE.wgsl DIR [chromium|firefox]" >&2
    exit 2
    ;;
esac
