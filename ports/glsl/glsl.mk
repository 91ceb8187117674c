# GLSL port, included at the end of the Makefile.
#   make gallery    spheres per metal and model through OSMesa: build/gallery/index.html
# The port's test is tests/shader_ports/test_glsl_port_osmesa.sh (run by make test; it builds its own
# binary because it links OSMesa).

GALLERY_METALS ?= au cu ag al cr
GALLERY_DIR    := $(BUILD)/gallery
GALLERY_SRC    := ports/glsl/host/gallery.c ports/glsl/host/glctx.c ports/glsl/host/png.c

.PHONY: gallery
gallery: $(BUILD)/fresnel $(BUILD)/glsl/gallery
	@mkdir -p $(GALLERY_DIR)
	@for m in $(GALLERY_METALS); do \
	    $(BUILD)/fresnel params --material $$m >$(GALLERY_DIR)/$$m.params.csv && \
	    $(BUILD)/fresnel curve --material $$m --samples 4097 --models exact >$(GALLERY_DIR)/$$m.curve.csv || exit 1; \
	done
	$(BUILD)/glsl/gallery ports/glsl $(GALLERY_DIR) $(GALLERY_METALS)

$(BUILD)/glsl/gallery: $(GALLERY_SRC) $(wildcard ports/glsl/host/*.h)
	@mkdir -p $(@D)
	@pkg-config --exists osmesa || { echo "gallery: OSMesa missing: apt-get install libosmesa6-dev"; exit 1; }
	$(CC) $(WARN) -O2 -Iports/glsl/host -o $@ $(GALLERY_SRC) $$(pkg-config --cflags --libs osmesa) -lm

# The recipe of a port that includes this one (ports/hlsl/, ports/msl/) as
# one file: its first prerequisite with ports/glsl/fresnel.glsl in place of
# its one #include "../glsl/fresnel.glsl".
define inline_glsl_port
	@mkdir -p $(@D)
	awk '$$0 == "#include \"../glsl/fresnel.glsl\"" { while ((getline l <"ports/glsl/fresnel.glsl") > 0) print l; n++; next } \
	    { print } END { if (n != 1) { print "no single #include of ../glsl/fresnel.glsl in $<" >"/dev/stderr"; exit 1 } }' \
	    $< >$@.tmp && mv $@.tmp $@
endef
