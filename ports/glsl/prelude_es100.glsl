#version 100
/* GLSL ES 1.00 (WebGL 1, GLES 2): then ports/glsl/fresnel.glsl. highp exists in
 * fragment shaders only where GL_FRAGMENT_PRECISION_HIGH is defined. */
precision mediump float;
