# MSL port, included at the end of the Makefile.
#   make msl     build/msl/fresnel.metal: the port as one file, for users who
#                vendor a single file: ports/msl/fresnel.metal with the file it
#                includes (ports/glsl/fresnel.glsl) in place of its #include
# tests/shader_ports/test_msl.sh compiles the port with every committed
# scene; make install puts it in share/fresnel/msl/.

.PHONY: msl
msl: $(BUILD)/msl/fresnel.metal

$(BUILD)/msl/fresnel.metal: ports/msl/fresnel.metal ports/glsl/fresnel.glsl
	$(inline_glsl_port)
