/* The few things a test program needs from the machine it runs on: text
 * out, an exit, and a marker the instruction counter can find in an
 * execution trace. Each ports/<target>/ implements them; the programs in
 * tests/ports/cross/ use nothing else (no libc, no float). */
#ifndef FRESNEL_PORT_H
#define FRESNEL_PORT_H

#include <stdint.h>

void port_puts(const char *s);
void port_exit(int status);
/* A call the trace parser recognises by address (ports/count.sh): never
 * inlined, does nothing else. */
void port_mark(uint32_t id);

/* Helpers on top of port_puts. */
void port_put_hex(uint32_t v);
void port_put_dec(uint32_t v);

#endif
