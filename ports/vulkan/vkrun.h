/* vkrun: a compute shader (SPIR-V) run once on a Vulkan device, no window,
 * no display: by default the CPU device, Mesa's lavapipe (Debian
 * mesa-vulkan-drivers; tests/shader_ports/test_vulkan.sh points the loader at its ICD
 * alone), or on request a GPU. Used by tests/shader_ports/vulkan_test.c for the GLSL 4.50
 * and HLSL ports.
 *
 * The shader's interface: descriptor set 0, binding 0 a storage buffer read
 * (the input floats), binding 1 a storage buffer written (the output
 * floats), up to 128 bytes of push constants and up to 8 int32
 * specialisation constants (constant_id 0, 1, ...); workgroups along x.
 * Specialisation constants are how a test selects what one pipeline
 * computes: the driver compiles only the branch they select.
 *
 *   vkrun v;
 *   vkrun_open(&v, "cpu", err, sizeof err);          instance, device, compute queue
 *   vkrun_pipeline(&v, words, nbytes, spec, nspec, push_bytes, &p, err, sizeof err);
 *   vkrun_dispatch(&v, &p, push, in, nin, out, nout, groups, err, sizeof err);
 *   vkrun_pipeline_free(&v, &p);
 *   vkrun_close(&v);
 * Each returns 0, or -1 with a message in err. */
#ifndef FRESNEL_VKRUN_H
#define FRESNEL_VKRUN_H

#include <stddef.h>
#include <stdint.h>

#include <vulkan/vulkan.h>

typedef struct vkrun {
    VkInstance instance;
    VkPhysicalDevice phys;
    VkDevice device;
    VkQueue queue;
    uint32_t queue_family;
    VkCommandPool pool;
    char device_name[VK_MAX_PHYSICAL_DEVICE_NAME_SIZE];
    char device_info[160]; /* index, type, vendor, driver version, Vulkan version */
    int float16;           /* 1: shaderFloat16 is enabled (Vulkan 1.2 devices that have it): Float16 modules run */
} vkrun;

typedef struct vkrun_pipe {
    VkShaderModule module;
    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    VkPipeline pipeline;
    uint32_t push_bytes;
} vkrun_pipe;

/* device: "cpu" (the first CPU device), "gpu" (the first discrete GPU, else
 * the first integrated or virtual one) or the index of a device in the
 * loader's list; a device that is not there fails with err listing those
 * that are. vkrun_device_valid: whether a string is one of these forms. */
int vkrun_open(vkrun *v, const char *device, char *err, size_t errsize);
int vkrun_device_valid(const char *device);
void vkrun_close(vkrun *v);

/* A compute pipeline from nbytes of SPIR-V (entry point "main"), with
 * spec[0..nspec-1] for constant_id 0..nspec-1 (nspec <= VKRUN_MAX_SPEC). */
#define VKRUN_MAX_SPEC 8
int vkrun_pipeline(vkrun *v, const uint32_t *words, size_t nbytes, const int32_t *spec, int nspec,
                   uint32_t push_bytes, vkrun_pipe *p, char *err, size_t errsize);
void vkrun_pipeline_free(vkrun *v, vkrun_pipe *p);

/* One dispatch of groups x 1 x 1 workgroups with push (p->push_bytes bytes;
 * NULL if 0), nin floats in, nout floats back (the output buffer starts
 * filled with NaN, so a value the shader does not write shows). */
int vkrun_dispatch(vkrun *v, const vkrun_pipe *p, const void *push, const float *in, size_t nin, float *out,
                   size_t nout, uint32_t groups, char *err, size_t errsize);

/* The whole file at path, its size in *nbytes; NULL if unreadable. free() it. */
uint32_t *vkrun_read_spirv(const char *path, size_t *nbytes);

#endif
