/* Instructions per fresnel_film_q15_rgb call on a Cortex-M0 (qemu trace,
 * ports/count.sh), for tests/cross/film_count.sh: 40 calls over cosines and
 * thicknesses 0..5000 nm spread over the domain, each after a port_mark;
 * the row "none" (the loop alone) is subtracted. */
#include "fresnel_film.h"
#include "port.h"

extern const fresnel_film_q15 *const film_gold;
volatile uint32_t bench_sink;

int main(void)
{
    uint32_t calls = 0;
    int i;
    port_puts("BENCH 40\nnone\nfilm_q15_rgb\nEND\n");
    for (i = 0; i < 40; i++) {
        port_mark(calls++);
        bench_sink += (uint32_t)i;
    }
    port_mark(calls++);
    for (i = 0; i < 40; i++) {
        fresnel_rgb_q15 r;
        port_mark(calls++);
        r = fresnel_film_q15_rgb(film_gold, (i * 821) & 32767, (i * 131) << 16);
        bench_sink += r.r + r.g + r.b;
    }
    port_mark(calls);
    return 0;
}
