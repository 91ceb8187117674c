/* A firmware that uses Schlick in fixed point for one material (gold at
 * 550 nm, F0 = 0.79155, code 25937) and nothing else: `make size` and
 * tests/ports/test_cross.sh check that it links fresnel_schlick_q15 and no other
 * part of the library. */
#include "fresnel_fixed.h"
#include "port.h"

static const int32_t gold_550_f0 = 25937;
volatile int32_t schlick_only_cos = 16384;

int main(void)
{
    port_put_dec(fresnel_schlick_q15(gold_550_f0, schlick_only_cos));
    port_puts("\n");
    return 0;
}
