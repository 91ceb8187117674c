#version 300 es
/* GLSL ES 3.00 (WebGL 2, GLES 3): then ports/glsl/fresnel.glsl. highp is
 * guaranteed in fragment shaders; fresnel.glsl uses it where mediump fails. */
precision mediump float;
