/* memcpy and memset for the freestanding ports. GCC may call them even
 * from code that never names them (struct copies, zeroing loops), so a
 * freestanding target has to provide them; the runtime itself has no other
 * external reference. The loops must not be turned back into calls to
 * themselves, hence the optimize attribute. */
#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);

__attribute__((optimize("no-tree-loop-distribute-patterns"))) void *memcpy(void *dst, const void *src, size_t n)
{
    unsigned char *d = dst;
    const unsigned char *s = src;
    while (n--)
        *d++ = *s++;
    return dst;
}

__attribute__((optimize("no-tree-loop-distribute-patterns"))) void *memset(void *dst, int c, size_t n)
{
    unsigned char *d = dst;
    while (n--)
        *d++ = (unsigned char)c;
    return dst;
}
