# WGSL port, included at the end of the Makefile.
#   make wgsl    build/wgsl/fresnel.wgsl: the port's functions translated from
#                ports/glsl/fresnel.glsl by the tool (fresnel gen --wgsl
#                without a scene); fresnel gen SCENE --wgsl writes the same
#                functions with a scene's constants, tables and functions;
#                build/wgsl/fresnel_f16.wgsl the same with `enable f16;`
#                (fresnel gen --wgsl-f16)
# tests/shader_ports/test_wgsl.sh runs them in headless Chromium's and
# Firefox's WebGPU (f16 in Firefox's).

.PHONY: wgsl
wgsl: $(BUILD)/wgsl/fresnel.wgsl $(BUILD)/wgsl/fresnel_f16.wgsl

$(BUILD)/wgsl/fresnel.wgsl: $(BUILD)/fresnel
	@mkdir -p $(@D)
	$(BUILD)/fresnel gen --wgsl -o $@

$(BUILD)/wgsl/fresnel_f16.wgsl: $(BUILD)/fresnel
	@mkdir -p $(@D)
	$(BUILD)/fresnel gen --wgsl-f16 -o $@
