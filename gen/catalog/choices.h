/* The other names a manifest or a command line may choose from, as data:
 * LUT spacings and gamut policies (their meaning: catalog/models.h and
 * 2_derive/derive.h, OUT-OF-GAMUT POLICY). */
#ifndef FRESNEL_CATALOG_CHOICES_H
#define FRESNEL_CATALOG_CHOICES_H

typedef enum gamut_policy { GAMUT_MAP, GAMUT_CLIP, GAMUT_KEEP } gamut_policy;

/* NULL-terminated, in lut_spacing's order (a manifest's lut_spacing key:
 * the first three) and gamut_policy's. */
extern const char *const lut_spacing_names[];
extern const char *const gamut_policy_names[];
/* The index of name in a NULL-terminated table of names, or -1. */
int catalog_choice(const char *const *names, const char *name);

#endif
