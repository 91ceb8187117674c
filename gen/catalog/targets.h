/* The renderers a scene or `fresnel params --for` may name as targets, as
 * data: each row's id is its name. What each one takes and its formula are
 * 2_derive/targets.c's table, indexed by these ids. */
#ifndef FRESNEL_CATALOG_TARGETS_H
#define FRESNEL_CATALOG_TARGETS_H

#define TARGET_CATALOG(X) X(openpbr) X(materialx) X(blender) X(unreal) X(gltf) X(filament) X(gulbrandsen)

#define TARGET_ID(id) TARGET_##id,
typedef enum target_id { TARGET_CATALOG(TARGET_ID) TARGETS } target_id;
#undef TARGET_ID
/* A row's name: its id as written. */
#define TARGET_NAME(id) #id

/* The names in id order, NULL-terminated. */
extern const char *const target_catalog_names[TARGETS + 1];
/* The id of the target named name; -1 if none. */
int target_parse(const char *name);
/* The names in id order, NULL-terminated (max includes the NULL). */
int target_names(const char **out, int max);

#endif
