/* See png.h. Layout: signature, IHDR, one IDAT holding a zlib stream of
 * stored blocks (each at most 65535 bytes) over the filtered rows (filter
 * byte 0 = none before each row), IEND. */
#include "png.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n)
{
    /* Bitwise CRC-32 (reflected polynomial 0xEDB88320): images are small, a
     * table would only save time nobody waits for. */
    size_t i;
    int k;
    crc = ~crc;
    for (i = 0; i < n; i++) {
        crc ^= p[i];
        for (k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

uint32_t png_adler32(uint32_t adler, const unsigned char *p, size_t n)
{
    uint32_t a = adler & 0xffffu, b = adler >> 16;
    size_t i;
    for (i = 0; i < n; i++) {
        a = (a + p[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return (b << 16) | a;
}

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* One chunk: length, type, data, CRC over type and data. */
static int chunk(FILE *f, const char *type, const unsigned char *data, size_t n)
{
    unsigned char hdr[8], crc[4];
    uint32_t c;
    put32(hdr, (uint32_t)n);
    memcpy(hdr + 4, type, 4);
    c = png_crc32(0, hdr + 4, 4);
    c = png_crc32(c, data, n);
    put32(crc, c);
    return fwrite(hdr, 1, 8, f) == 8 && (n == 0 || fwrite(data, 1, n, f) == n) && fwrite(crc, 1, 4, f) == 4;
}

int png_write_rgb8(const char *path, int w, int h, const unsigned char *rgb)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    size_t row = (size_t)w * 3 + 1, raw_n = row * (size_t)h;
    size_t nblocks = raw_n / 65535 + 1, z_n = 2 + raw_n + 5 * nblocks + 4;
    unsigned char ihdr[13], *raw, *z, *q;
    size_t i, left;
    int y, ok;
    FILE *f;
    if (w <= 0 || h <= 0)
        return -1;
    raw = malloc(raw_n);
    z = malloc(z_n);
    if (!raw || !z) {
        free(raw);
        free(z);
        return -1;
    }
    for (y = 0; y < h; y++) {
        raw[(size_t)y * row] = 0;
        memcpy(raw + (size_t)y * row + 1, rgb + (size_t)y * (size_t)w * 3, (size_t)w * 3);
    }
    q = z;
    *q++ = 0x78; /* deflate, 32 KiB window */
    *q++ = 0x01; /* no preset dictionary, fastest; 0x7801 % 31 == 0 */
    for (i = 0, left = raw_n; i < nblocks; i++) {
        size_t n = left < 65535 ? left : 65535;
        *q++ = (unsigned char)(i + 1 == nblocks); /* BFINAL, BTYPE 00 = stored */
        *q++ = (unsigned char)(n & 0xff);
        *q++ = (unsigned char)(n >> 8);
        *q++ = (unsigned char)(~n & 0xff);
        *q++ = (unsigned char)((~n >> 8) & 0xff);
        memcpy(q, raw + (raw_n - left), n);
        q += n;
        left -= n;
    }
    put32(q, png_adler32(1, raw, raw_n));
    q += 4;
    put32(ihdr, (uint32_t)w);
    put32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;  /* bits per channel */
    ihdr[9] = 2;  /* truecolour */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering (each row says "none") */
    ihdr[12] = 0; /* no interlace */
    f = fopen(path, "wb");
    ok = f && fwrite(sig, 1, 8, f) == 8 && chunk(f, "IHDR", ihdr, 13) && chunk(f, "IDAT", z, (size_t)(q - z)) &&
         chunk(f, "IEND", NULL, 0);
    if (f && fclose(f) != 0)
        ok = 0;
    free(raw);
    free(z);
    return ok ? 0 : -1;
}
