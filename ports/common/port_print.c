/* Number printing on top of port_puts, without libc or division (Cortex-M0
 * has no divide instruction; decimal digits by repeated subtraction of
 * powers of ten). */
#include "port.h"

void port_put_hex(uint32_t v)
{
    char buf[11];
    int i;
    buf[0] = '0';
    buf[1] = 'x';
    for (i = 0; i < 8; i++) {
        uint32_t d = (v >> (28 - 4 * i)) & 15u;
        buf[2 + i] = (char)(d < 10 ? '0' + d : 'a' + d - 10);
    }
    buf[10] = '\0';
    port_puts(buf);
}

void port_put_dec(uint32_t v)
{
    static const uint32_t pow10[10] = {1000000000u, 100000000u, 10000000u, 1000000u, 100000u,
                                       10000u,      1000u,      100u,      10u,      1u};
    char buf[11];
    int i, n = 0;
    for (i = 0; i < 10; i++) {
        char d = '0';
        while (v >= pow10[i]) {
            v -= pow10[i];
            d++;
        }
        if (d != '0' || n || i == 9)
            buf[n++] = d;
    }
    buf[n] = '\0';
    port_puts(buf);
}
