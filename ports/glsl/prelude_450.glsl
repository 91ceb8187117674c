#version 450
/* GLSL 4.50 for Vulkan (glslangValidator -V, SPIR-V): then a default float
 * precision and ports/glsl/fresnel.glsl. With `precision mediump float;` the
 * mediump-safe functions' values carry SPIR-V RelaxedPrecision; the highp
 * functions stay binary32. ports/vulkan/ runs it as a compute shader. */
