/* See glctx.h. */
#include "glctx.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int glctx_open(glctx *g, int width, int height, char *err, size_t errsize)
{
    static const int profiles[2] = {OSMESA_CORE_PROFILE, OSMESA_COMPAT_PROFILE};
    /* Corners of one triangle that covers the [-1, 1]^2 viewport: no seam
     * down a diagonal, every pixel shaded once. */
    static const float tri[6] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
    int i;
    memset(g, 0, sizeof *g);
    for (i = 0; i < 2 && !g->ctx; i++) {
        int attr[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                      OSMESA_PROFILE, profiles[i], OSMESA_CONTEXT_MAJOR_VERSION, 3,
                      OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
        g->ctx = OSMesaCreateContextAttribs(attr, NULL);
    }
    if (!g->ctx) {
        snprintf(err, errsize, "OSMesaCreateContextAttribs failed for GL 3.3 core and compatibility");
        return -1;
    }
    g->width = width;
    g->height = height;
    g->pixels = calloc((size_t)width * (size_t)height, 4);
    if (!g->pixels || !OSMesaMakeCurrent(g->ctx, g->pixels, GL_UNSIGNED_BYTE, width, height)) {
        snprintf(err, errsize, "OSMesaMakeCurrent failed (%dx%d RGBA8)", width, height);
        glctx_close(g);
        return -1;
    }
    /* Rows of pixels from the bottom, as glReadPixels returns them. */
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    glGenVertexArrays(1, &g->vao);
    glBindVertexArray(g->vao);
    glGenBuffers(1, &g->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, g->vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnableVertexAttribArray(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    return 0;
}

void glctx_close(glctx *g)
{
    if (g->ctx)
        OSMesaDestroyContext(g->ctx);
    free(g->pixels);
    memset(g, 0, sizeof *g);
}

char *glctx_read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s = NULL;
    long n;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        s = malloc((size_t)n + 1);
        if (s && fread(s, 1, (size_t)n, f) != (size_t)n) {
            free(s);
            s = NULL;
        } else if (s) {
            s[n] = '\0';
        }
    }
    fclose(f);
    return s;
}

GLuint glctx_shader(GLenum type, const char *const *parts, int nparts, char *log, size_t logsize)
{
    GLuint s = glCreateShader(type);
    GLint ok = 0;
    glShaderSource(s, nparts, (const GLchar *const *)parts, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    log[0] = '\0';
    if (!ok) {
        glGetShaderInfoLog(s, (GLsizei)logsize, NULL, log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

GLuint glctx_program(GLuint vs, GLuint fs, char *log, size_t logsize)
{
    GLuint p = glCreateProgram();
    GLint ok = 0;
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glBindAttribLocation(p, 0, "fr_pos");
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    glDeleteShader(vs);
    glDeleteShader(fs);
    log[0] = '\0';
    if (!ok) {
        glGetProgramInfoLog(p, (GLsizei)logsize, NULL, log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

const char *glctx_vertex_source(int es, int version)
{
    /* fr_uv is highp: ES 1.00's gl_FragCoord is mediump, and on llvmpipe a
     * mediump operand anywhere in the expression written to gl_FragColor
     * (itself mediump in ES 1.00) rounds the whole output to binary16. */
    if (es && version < 300)
        return "#version 100\nattribute vec2 fr_pos;\nvarying highp vec2 fr_uv;\n"
               "void main() { fr_uv = fr_pos * 0.5 + 0.5; gl_Position = vec4(fr_pos, 0.0, 1.0); }\n";
    if (es)
        return "#version 300 es\nin vec2 fr_pos;\nout highp vec2 fr_uv;\n"
               "void main() { fr_uv = fr_pos * 0.5 + 0.5; gl_Position = vec4(fr_pos, 0.0, 1.0); }\n";
    return "#version 330 core\nin vec2 fr_pos;\nout vec2 fr_uv;\n"
           "void main() { fr_uv = fr_pos * 0.5 + 0.5; gl_Position = vec4(fr_pos, 0.0, 1.0); }\n";
}

void glctx_draw(glctx *g)
{
    glBindVertexArray(g->vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

GLuint glctx_float_target(int w, int h, GLuint *tex)
{
    GLuint fbo;
    glGenTextures(1, tex);
    glBindTexture(GL_TEXTURE_2D, *tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *tex, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return 0;
    }
    return fbo;
}

GLuint glctx_r32f_texture(int w, int h, const float *data)
{
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, w, h, 0, GL_RED, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}
