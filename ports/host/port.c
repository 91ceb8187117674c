/* The port interface on the build machine (stdio), for the same test
 * programs the cross targets run: their output is the reference the
 * targets' output is compared with. */
#include <stdio.h>
#include <stdlib.h>

#include "port.h"

void port_puts(const char *s) { fputs(s, stdout); }
void port_exit(int status)
{
    fflush(stdout);
    exit(status);
}
void port_mark(uint32_t id) { (void)id; }
