# WGSL port, included at the end of the Makefile.
#   make wgsl    build/wgsl/fresnel.wgsl: the port's functions translated from
#                ports/glsl/fresnel.glsl by the tool (fresnel gen --wgsl
#                without a scene); fresnel gen SCENE --wgsl writes the same
#                functions with a scene's constants, tables and functions
# tests/shader_ports/test_wgsl.sh runs both in headless Chromium's WebGPU.

.PHONY: wgsl
wgsl: $(BUILD)/wgsl/fresnel.wgsl

$(BUILD)/wgsl/fresnel.wgsl: $(BUILD)/fresnel
	@mkdir -p $(@D)
	$(BUILD)/fresnel gen --wgsl -o $@
