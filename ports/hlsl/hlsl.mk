# HLSL port, included at the end of the Makefile.
#   make hlsl    build/hlsl/fresnel.hlsl: the port as one file, for users who
#                vendor a single file: ports/hlsl/fresnel.hlsl with the file it
#                includes (ports/glsl/fresnel.glsl) in place of its #include
# tests/shader_ports/test_vulkan.sh compiles it with every committed scene; make install
# puts it in share/fresnel/hlsl/.

.PHONY: hlsl
hlsl: $(BUILD)/hlsl/fresnel.hlsl

$(BUILD)/hlsl/fresnel.hlsl: ports/hlsl/fresnel.hlsl ports/glsl/fresnel.glsl
	$(inline_glsl_port)
