/* Off-screen GL for the GLSL port's test and gallery: an OSMesa context,
 * shader sources assembled from ports/glsl/ files, programs with their info
 * logs, float render targets. Host only (malloc, stdio). */
#ifndef FRESNEL_GLCTX_H
#define FRESNEL_GLCTX_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stddef.h>

typedef struct glctx {
    OSMesaContext ctx;
    unsigned char *pixels; /* the default framebuffer: RGBA8, width x height */
    int width, height;
    GLuint vao, vbo;       /* one triangle covering the viewport */
} glctx;

/* A core-profile context (the highest version Mesa gives; OSMesa takes 3.3
 * as a minimum), falling back to compatibility. 0 on success; on failure a
 * message in err. */
int glctx_open(glctx *g, int width, int height, char *err, size_t errsize);
void glctx_close(glctx *g);

/* Whole file into a malloc'd, NUL-terminated string; NULL if unreadable. */
char *glctx_read_file(const char *path);

/* Compile a shader from parts concatenated in order. Returns the shader, or
 * 0 with the info log (and the failing source's line count) in log. */
GLuint glctx_shader(GLenum type, const char *const *parts, int nparts, char *log, size_t logsize);

/* Link vs and fs (attribute 0 is "fr_pos", the triangle's corners). Returns
 * the program or 0 with the info log in log. The shaders are deleted. */
GLuint glctx_program(GLuint vs, GLuint fs, char *log, size_t logsize);

/* A vertex shader for the dialect (es, version: 100, 300 or 330) that
 * passes fr_pos through and gives the fragment shader highp fr_uv in [0, 1]
 * across the viewport. */
const char *glctx_vertex_source(int es, int version);

/* Draw the triangle with the bound program into the bound framebuffer. */
void glctx_draw(glctx *g);

/* An RGBA32F texture of w x h as colour attachment 0 of a new framebuffer
 * (left bound). Returns the framebuffer, 0 if incomplete. */
GLuint glctx_float_target(int w, int h, GLuint *tex);

/* A single-channel binary32 texture (GL_R32F, NEAREST, clamped) holding data
 * (w x h, rows bottom to top). */
GLuint glctx_r32f_texture(int w, int h, const float *data);

#endif
