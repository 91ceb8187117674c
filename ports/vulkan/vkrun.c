/* vkrun (see vkrun.h): Vulkan 1.0 compute, host-visible coherent buffers,
 * one fence per dispatch. Every object a call creates is destroyed before
 * it returns, except what vkrun_open and vkrun_pipeline hand back. */
#include "vkrun.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(char *err, size_t errsize, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errsize, fmt, ap);
    va_end(ap);
    return -1;
}

#define VKCHECK(call, what)                                                                        \
    do {                                                                                           \
        VkResult r_ = (call);                                                                      \
        if (r_ != VK_SUCCESS) {                                                                    \
            fail(err, errsize, "%s failed (VkResult %d)", (what), (int)r_);                        \
            goto done;                                                                             \
        }                                                                                          \
    } while (0)

static const char *type_name(VkPhysicalDeviceType t)
{
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete gpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual gpu";
    default: return "other";
    }
}

/* Which of devs[0..n-1] the choice names, or -1: "cpu" the first CPU
 * device, "gpu" the first discrete GPU, else the first integrated or
 * virtual one, a decimal number that index. */
static int choose(const VkPhysicalDeviceProperties *pr, uint32_t n, const char *device)
{
    static const VkPhysicalDeviceType gpus[] = {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU,
                                                VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                                VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU};
    uint32_t i, k;
    char *end;
    long index;
    if (!strcmp(device, "cpu")) {
        for (i = 0; i < n; i++)
            if (pr[i].deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
                return (int)i;
        return -1;
    }
    if (!strcmp(device, "gpu")) {
        for (k = 0; k < sizeof gpus / sizeof gpus[0]; k++)
            for (i = 0; i < n; i++)
                if (pr[i].deviceType == gpus[k])
                    return (int)i;
        return -1;
    }
    index = strtol(device, &end, 10);
    return *device && !*end && index >= 0 && index < (long)n ? (int)index : -1;
}

int vkrun_device_valid(const char *device)
{
    const char *p = device;
    if (!strcmp(device, "cpu") || !strcmp(device, "gpu"))
        return 1;
    while (*p >= '0' && *p <= '9')
        p++;
    return p != device && !*p && p - device <= 4;
}

int vkrun_open(vkrun *v, const char *device, char *err, size_t errsize)
{
    VkApplicationInfo app;
    VkInstanceCreateInfo ici;
    VkPhysicalDevice devs[16];
    VkPhysicalDeviceProperties props[16];
    uint32_t ndev = 16, i, nq = 0;
    VkQueueFamilyProperties qf[16];
    float prio = 1.0f;
    VkDeviceQueueCreateInfo qci;
    VkDeviceCreateInfo dci;
    VkPhysicalDeviceShaderFloat16Int8Features f16;
    VkCommandPoolCreateInfo pci;
    int found;
    memset(v, 0, sizeof *v);
    memset(&app, 0, sizeof app);
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "fresnel vkrun";
    app.apiVersion = VK_API_VERSION_1_2; /* the highest the device may use; 1.0 devices still work */
    memset(&ici, 0, sizeof ici);
    ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ici.pApplicationInfo = &app;
    VKCHECK(vkCreateInstance(&ici, NULL, &v->instance), "vkCreateInstance (is a Vulkan driver installed?)");
    {
        VkResult r = vkEnumeratePhysicalDevices(v->instance, &ndev, devs);
        if (r != VK_SUCCESS && r != VK_INCOMPLETE) {
            fail(err, errsize, "vkEnumeratePhysicalDevices failed (VkResult %d)", (int)r);
            goto done;
        }
    }
    for (i = 0; i < ndev; i++)
        vkGetPhysicalDeviceProperties(devs[i], &props[i]);
    found = choose(props, ndev, device);
    if (found < 0) {
        /* the devices there are, so that the message says what to pick */
        size_t len;
        fail(err, errsize, "no Vulkan device '%s' among the %u the loader lists:", device, ndev);
        for (i = 0; i < ndev && (len = strlen(err)) + 1 < errsize; i++)
            snprintf(err + len, errsize - len, " %u = %s (%s);", i, props[i].deviceName,
                     type_name(props[i].deviceType));
        if (!strcmp(device, "cpu") && (len = strlen(err)) + 1 < errsize)
            snprintf(err + len, errsize - len, " install Debian's mesa-vulkan-drivers (lavapipe)");
        goto done;
    }
    snprintf(v->device_name, sizeof v->device_name, "%s", props[found].deviceName);
    snprintf(v->device_info, sizeof v->device_info,
             "device %d of %u, %s, vendor 0x%04x, driver version 0x%08x, Vulkan %u.%u.%u", found, ndev, type_name(props[found].deviceType), props[found].vendorID, props[found].driverVersion,
             VK_VERSION_MAJOR(props[found].apiVersion), VK_VERSION_MINOR(props[found].apiVersion),
             VK_VERSION_PATCH(props[found].apiVersion));
    v->phys = devs[found];
    vkGetPhysicalDeviceQueueFamilyProperties(v->phys, &nq, NULL);
    if (nq > 16)
        nq = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(v->phys, &nq, qf);
    for (i = 0; i < nq; i++)
        if (qf[i].queueFlags & VK_QUEUE_COMPUTE_BIT)
            break;
    if (i == nq) {
        fail(err, errsize, "%s has no compute queue", v->device_name);
        goto done;
    }
    v->queue_family = i;
    memset(&qci, 0, sizeof qci);
    qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    qci.queueFamilyIndex = v->queue_family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &prio;
    memset(&dci, 0, sizeof dci);
    dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    /* explicit 16-bit floats in shaders (SPIR-V Float16), where the device
     * has them: core in Vulkan 1.2 */
    memset(&f16, 0, sizeof f16);
    f16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES;
    if (props[found].apiVersion >= VK_API_VERSION_1_2) {
        VkPhysicalDeviceFeatures2 f2;
        memset(&f2, 0, sizeof f2);
        f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
        f2.pNext = &f16;
        vkGetPhysicalDeviceFeatures2(v->phys, &f2);
        if (f16.shaderFloat16) {
            f16.shaderInt8 = VK_FALSE;
            f16.pNext = NULL;
            dci.pNext = &f16;
            v->float16 = 1;
        }
    }
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    VKCHECK(vkCreateDevice(v->phys, &dci, NULL, &v->device), "vkCreateDevice");
    vkGetDeviceQueue(v->device, v->queue_family, 0, &v->queue);
    memset(&pci, 0, sizeof pci);
    pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pci.queueFamilyIndex = v->queue_family;
    VKCHECK(vkCreateCommandPool(v->device, &pci, NULL, &v->pool), "vkCreateCommandPool");
    return 0;
done:
    vkrun_close(v);
    return -1;
}

void vkrun_close(vkrun *v)
{
    if (v->device) {
        if (v->pool)
            vkDestroyCommandPool(v->device, v->pool, NULL);
        vkDestroyDevice(v->device, NULL);
    }
    if (v->instance)
        vkDestroyInstance(v->instance, NULL);
    memset(v, 0, sizeof *v);
}

int vkrun_pipeline(vkrun *v, const uint32_t *words, size_t nbytes, const int32_t *spec, int nspec,
                   uint32_t push_bytes, vkrun_pipe *p, char *err, size_t errsize)
{
    VkSpecializationMapEntry me[VKRUN_MAX_SPEC];
    VkSpecializationInfo si;
    VkShaderModuleCreateInfo smci;
    VkDescriptorSetLayoutBinding b[2];
    VkDescriptorSetLayoutCreateInfo dslci;
    VkPushConstantRange pcr;
    VkPipelineLayoutCreateInfo plci;
    VkComputePipelineCreateInfo cpci;
    int i;
    memset(p, 0, sizeof *p);
    p->push_bytes = push_bytes;
    if (nspec < 0 || nspec > VKRUN_MAX_SPEC)
        return fail(err, errsize, "%d specialisation constants (at most %d)", nspec, VKRUN_MAX_SPEC);
    for (i = 0; i < nspec; i++) {
        me[i].constantID = (uint32_t)i;
        me[i].offset = (uint32_t)i * (uint32_t)sizeof(int32_t);
        me[i].size = sizeof(int32_t);
    }
    si.mapEntryCount = (uint32_t)nspec;
    si.pMapEntries = me;
    si.dataSize = (size_t)nspec * sizeof(int32_t);
    si.pData = spec;
    memset(&smci, 0, sizeof smci);
    smci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    smci.codeSize = nbytes;
    smci.pCode = words;
    VKCHECK(vkCreateShaderModule(v->device, &smci, NULL, &p->module), "vkCreateShaderModule");
    memset(b, 0, sizeof b);
    for (i = 0; i < 2; i++) {
        b[i].binding = (uint32_t)i;
        b[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        b[i].descriptorCount = 1;
        b[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    memset(&dslci, 0, sizeof dslci);
    dslci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    dslci.bindingCount = 2;
    dslci.pBindings = b;
    VKCHECK(vkCreateDescriptorSetLayout(v->device, &dslci, NULL, &p->set_layout), "vkCreateDescriptorSetLayout");
    memset(&pcr, 0, sizeof pcr);
    pcr.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    pcr.size = push_bytes;
    memset(&plci, 0, sizeof plci);
    plci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &p->set_layout;
    plci.pushConstantRangeCount = push_bytes ? 1 : 0;
    plci.pPushConstantRanges = push_bytes ? &pcr : NULL;
    VKCHECK(vkCreatePipelineLayout(v->device, &plci, NULL, &p->layout), "vkCreatePipelineLayout");
    memset(&cpci, 0, sizeof cpci);
    cpci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = p->module;
    cpci.stage.pName = "main";
    cpci.stage.pSpecializationInfo = nspec ? &si : NULL;
    cpci.layout = p->layout;
    VKCHECK(vkCreateComputePipelines(v->device, VK_NULL_HANDLE, 1, &cpci, NULL, &p->pipeline),
            "vkCreateComputePipelines");
    return 0;
done:
    vkrun_pipeline_free(v, p);
    return -1;
}

void vkrun_pipeline_free(vkrun *v, vkrun_pipe *p)
{
    if (p->pipeline)
        vkDestroyPipeline(v->device, p->pipeline, NULL);
    if (p->layout)
        vkDestroyPipelineLayout(v->device, p->layout, NULL);
    if (p->set_layout)
        vkDestroyDescriptorSetLayout(v->device, p->set_layout, NULL);
    if (p->module)
        vkDestroyShaderModule(v->device, p->module, NULL);
    memset(p, 0, sizeof *p);
}

/* A host-visible, host-coherent storage buffer of size bytes. */
static int make_buffer(vkrun *v, VkDeviceSize size, VkBuffer *buf, VkDeviceMemory *mem, char *err, size_t errsize)
{
    VkBufferCreateInfo bci;
    VkMemoryRequirements req;
    VkPhysicalDeviceMemoryProperties mp;
    VkMemoryAllocateInfo mai;
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t i;
    memset(&bci, 0, sizeof bci);
    bci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bci.size = size;
    bci.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VKCHECK(vkCreateBuffer(v->device, &bci, NULL, buf), "vkCreateBuffer");
    vkGetBufferMemoryRequirements(v->device, *buf, &req);
    vkGetPhysicalDeviceMemoryProperties(v->phys, &mp);
    for (i = 0; i < mp.memoryTypeCount; i++)
        if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want)
            break;
    if (i == mp.memoryTypeCount)
        return fail(err, errsize, "no host-visible coherent memory type");
    memset(&mai, 0, sizeof mai);
    mai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = i;
    VKCHECK(vkAllocateMemory(v->device, &mai, NULL, mem), "vkAllocateMemory");
    VKCHECK(vkBindBufferMemory(v->device, *buf, *mem, 0), "vkBindBufferMemory");
    return 0;
done:
    return -1;
}

int vkrun_dispatch(vkrun *v, const vkrun_pipe *p, const void *push, const float *in, size_t nin, float *out,
                   size_t nout, uint32_t groups, char *err, size_t errsize)
{
    VkBuffer buf[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkDeviceMemory mem[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    VkDeviceSize size[2];
    VkDescriptorPool dpool = VK_NULL_HANDLE;
    VkDescriptorPoolSize ps;
    VkDescriptorPoolCreateInfo dpci;
    VkDescriptorSetAllocateInfo dsai;
    VkDescriptorSet set;
    VkDescriptorBufferInfo dbi[2];
    VkWriteDescriptorSet w[2];
    VkCommandBufferAllocateInfo cbai;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    VkCommandBufferBeginInfo cbbi;
    VkMemoryBarrier mb;
    VkSubmitInfo si;
    VkFenceCreateInfo fci;
    VkFence fence = VK_NULL_HANDLE;
    void *map;
    int i, status = -1;
    size_t k;
    size[0] = (VkDeviceSize)(nin ? nin : 1) * sizeof(float);
    size[1] = (VkDeviceSize)(nout ? nout : 1) * sizeof(float);
    for (i = 0; i < 2; i++)
        if (make_buffer(v, size[i], &buf[i], &mem[i], err, errsize))
            goto done;
    VKCHECK(vkMapMemory(v->device, mem[0], 0, size[0], 0, &map), "vkMapMemory");
    memcpy(map, in, nin * sizeof(float));
    vkUnmapMemory(v->device, mem[0]);
    VKCHECK(vkMapMemory(v->device, mem[1], 0, size[1], 0, &map), "vkMapMemory");
    for (k = 0; k < nout; k++)
        ((float *)map)[k] = (float)NAN;
    vkUnmapMemory(v->device, mem[1]);

    memset(&ps, 0, sizeof ps);
    ps.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    ps.descriptorCount = 2;
    memset(&dpci, 0, sizeof dpci);
    dpci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dpci.maxSets = 1;
    dpci.poolSizeCount = 1;
    dpci.pPoolSizes = &ps;
    VKCHECK(vkCreateDescriptorPool(v->device, &dpci, NULL, &dpool), "vkCreateDescriptorPool");
    memset(&dsai, 0, sizeof dsai);
    dsai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    dsai.descriptorPool = dpool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &p->set_layout;
    VKCHECK(vkAllocateDescriptorSets(v->device, &dsai, &set), "vkAllocateDescriptorSets");
    memset(w, 0, sizeof w);
    for (i = 0; i < 2; i++) {
        dbi[i].buffer = buf[i];
        dbi[i].offset = 0;
        dbi[i].range = VK_WHOLE_SIZE;
        w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w[i].dstSet = set;
        w[i].dstBinding = (uint32_t)i;
        w[i].descriptorCount = 1;
        w[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w[i].pBufferInfo = &dbi[i];
    }
    vkUpdateDescriptorSets(v->device, 2, w, 0, NULL);

    memset(&cbai, 0, sizeof cbai);
    cbai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    cbai.commandPool = v->pool;
    cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbai.commandBufferCount = 1;
    VKCHECK(vkAllocateCommandBuffers(v->device, &cbai, &cb), "vkAllocateCommandBuffers");
    memset(&cbbi, 0, sizeof cbbi);
    cbbi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    cbbi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VKCHECK(vkBeginCommandBuffer(cb, &cbbi), "vkBeginCommandBuffer");
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, p->pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, p->layout, 0, 1, &set, 0, NULL);
    if (p->push_bytes)
        vkCmdPushConstants(cb, p->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, p->push_bytes, push);
    vkCmdDispatch(cb, groups, 1, 1);
    /* the shader's writes visible to the host's reads after the fence */
    memset(&mb, 0, sizeof mb);
    mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    mb.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, NULL, 0,
                         NULL);
    VKCHECK(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
    memset(&fci, 0, sizeof fci);
    fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VKCHECK(vkCreateFence(v->device, &fci, NULL, &fence), "vkCreateFence");
    memset(&si, 0, sizeof si);
    si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cb;
    VKCHECK(vkQueueSubmit(v->queue, 1, &si, fence), "vkQueueSubmit");
    VKCHECK(vkWaitForFences(v->device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    VKCHECK(vkMapMemory(v->device, mem[1], 0, size[1], 0, &map), "vkMapMemory");
    memcpy(out, map, nout * sizeof(float));
    vkUnmapMemory(v->device, mem[1]);
    status = 0;
done:
    if (fence)
        vkDestroyFence(v->device, fence, NULL);
    if (cb)
        vkFreeCommandBuffers(v->device, v->pool, 1, &cb);
    if (dpool)
        vkDestroyDescriptorPool(v->device, dpool, NULL);
    for (i = 0; i < 2; i++) {
        if (buf[i])
            vkDestroyBuffer(v->device, buf[i], NULL);
        if (mem[i])
            vkFreeMemory(v->device, mem[i], NULL);
    }
    return status;
}

uint32_t *vkrun_read_spirv(const char *path, size_t *nbytes)
{
    FILE *f = fopen(path, "rb");
    uint32_t *w = NULL;
    long n;
    if (!f)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 && n % 4 == 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (w = malloc((size_t)n)) != NULL) {
        if (fread(w, 1, (size_t)n, f) != (size_t)n) {
            free(w);
            w = NULL;
        } else {
            *nbytes = (size_t)n;
        }
    }
    fclose(f);
    return w;
}
