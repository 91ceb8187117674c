#version 330 core
/* Desktop GLSL 3.30: then ports/glsl/fresnel.glsl. Precision qualifiers are
 * accepted and ignored: everything is binary32. */
