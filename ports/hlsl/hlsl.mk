# HLSL port, included at the end of the Makefile.
#   make hlsl    build/hlsl/fresnel.hlsl: the port as one file, for users who
#                vendor a single file: ports/hlsl/fresnel.hlsl with the file it
#                includes (ports/glsl/fresnel.glsl) in place of its #include
# tests/shader_ports/test_vulkan.sh compiles it with every committed scene; make install
# puts it in share/fresnel/hlsl/.

.PHONY: hlsl
hlsl: $(BUILD)/hlsl/fresnel.hlsl

$(BUILD)/hlsl/fresnel.hlsl: ports/hlsl/fresnel.hlsl ports/glsl/fresnel.glsl
	@mkdir -p $(@D)
	awk '$$0 == "#include \"../glsl/fresnel.glsl\"" { while ((getline l <"ports/glsl/fresnel.glsl") > 0) print l; n++; next } \
	    { print } END { if (n != 1) { print "hlsl.mk: no single #include of ../glsl/fresnel.glsl in ports/hlsl/fresnel.hlsl" >"/dev/stderr"; exit 1 } }' \
	    ports/hlsl/fresnel.hlsl >$@.tmp && mv $@.tmp $@
