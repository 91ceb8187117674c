/* A minimal PNG writer for the gallery: 8-bit RGB, no compression (zlib
 * stream of stored deflate blocks), so no zlib or libpng is needed. */
#ifndef FRESNEL_PNG_H
#define FRESNEL_PNG_H

#include <stddef.h>
#include <stdint.h>

/* rgb: h rows of w pixels, top row first, 3 bytes per pixel. 0 on success. */
int png_write_rgb8(const char *path, int w, int h, const unsigned char *rgb);

/* The two checksums PNG needs, exposed for the test. */
uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n);
uint32_t png_adler32(uint32_t adler, const unsigned char *p, size_t n);

#endif
