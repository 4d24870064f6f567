#include "vk/VulkanContext.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <dlfcn.h>
#include <link.h>

#include "core/DriverShaderCache.h"
#include "core/DriverTable.h"
#include "core/Error.h"

namespace sb {
namespace {

// ---- the sanitizer build ----------------------------------------------------------------------------
// GCC says __SANITIZE_ADDRESS__; clang 14 (the asan preset) says __has_feature(address_sanitizer).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SB_ADDRESS_SANITIZER 1
#endif
#endif

/// Under AddressSanitizer only: keeps the Vulkan driver and layer libraries the loader opened mapped until
/// the process exits. The loader unloads them in vkDestroyInstance, and what they keep for the process
/// (reachable from their globals while they are mapped) then looks to LeakSanitizer, which reports at
/// exit, like a leak in "<unknown module>" that no suppression can name (measured: 128 bytes per run
/// from lavapipe). Pinned, it stays reachable, and a leak of ours is still reported. Nothing changes in
/// the normal build.
void pinVulkanLibraries() {
#if defined(__SANITIZE_ADDRESS__) || defined(SB_ADDRESS_SANITIZER)
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const std::string path = info->dlpi_name ? info->dlpi_name : "";
            if (path.find("libvulkan_") != std::string::npos || path.find("libVkLayer_") != std::string::npos)
                dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
#endif
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string resultName(VkResult result) {
    switch (result) {
    case VK_SUCCESS:
        return "VK_SUCCESS";
    case VK_NOT_READY:
        return "VK_NOT_READY";
    case VK_TIMEOUT:
        return "VK_TIMEOUT";
    case VK_INCOMPLETE:
        return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
        return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
        return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED:
        return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST:
        return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED:
        return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT:
        return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT:
        return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT:
        return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
        return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_TOO_MANY_OBJECTS:
        return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_FORMAT_NOT_SUPPORTED:
        return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_FRAGMENTED_POOL:
        return "VK_ERROR_FRAGMENTED_POOL";
    case VK_ERROR_OUT_OF_POOL_MEMORY:
        return "VK_ERROR_OUT_OF_POOL_MEMORY";
    default:
        return "VkResult " + std::to_string(static_cast<int>(result));
    }
}

std::string typeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual";
    default:
        return "other";
    }
}

std::string versionString(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

/// The API version this code asks for: 1.3 where the loader has it, else 1.2.
uint32_t instanceApiVersion() {
    uint32_t version = VK_API_VERSION_1_0;
    auto enumerate = reinterpret_cast<PFN_vkEnumerateInstanceVersion>(
        vkGetInstanceProcAddr(VK_NULL_HANDLE, "vkEnumerateInstanceVersion"));
    if (enumerate) enumerate(&version);
    return version >= VK_API_VERSION_1_3 ? VK_API_VERSION_1_3 : VK_API_VERSION_1_2;
}

/// vkCreateInstance failing: no driver (the loader found no ICD, or none that initialises) is the
/// machine's lack; anything else is a failure.
[[noreturn]] void instanceFailed(VkResult result) {
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
        throw Error("vulkan: no Vulkan driver (vkCreateInstance: " + resultName(result) +
                        "; install mesa-vulkan-drivers for lavapipe, or check VK_ICD_FILENAMES)",
                    ExitCode::Unsupported);
    if (result == VK_ERROR_LAYER_NOT_PRESENT)
        throw Error(std::string("vulkan: validation layer ") + kValidationLayer +
                        " not present (install the Debian package vulkan-validationlayers)",
                    ExitCode::Unsupported);
    throw Error("vulkan: vkCreateInstance failed: " + resultName(result), ExitCode::Failure);
}

VkInstance createBareInstance() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "shadowbench";
    app.apiVersion = instanceApiVersion();
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result != VK_SUCCESS) instanceFailed(result);
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    uint32_t count = 0;
    VkResult result = vkEnumeratePhysicalDevices(instance, &count, nullptr);
    if (result == VK_ERROR_INITIALIZATION_FAILED)
        throw Error("vulkan: no Vulkan device (vkEnumeratePhysicalDevices: " + resultName(result) + ")",
                    ExitCode::Unsupported);
    VulkanContext::check(result, "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    if (count)
        VulkanContext::check(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
                             "vkEnumeratePhysicalDevices");
    devices.resize(count);
    if (devices.empty())
        throw Error("vulkan: no Vulkan device (the loader lists none)", ExitCode::Unsupported);
    return devices;
}

VulkanDeviceInfo describe(VkPhysicalDevice device, int index, VkPhysicalDeviceProperties* out = nullptr) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &driver;
    vkGetPhysicalDeviceProperties2(device, &props);
    if (out) *out = props.properties;
    VulkanDeviceInfo info;
    info.index = index;
    info.name = props.properties.deviceName;
    info.type = typeName(props.properties.deviceType);
    info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
    info.driverInfo = driver.driverInfo;
    info.apiVersion = versionString(props.properties.apiVersion);
    return info;
}

std::string deviceList(const std::vector<VulkanDeviceInfo>& devices) {
    std::string out;
    for (const VulkanDeviceInfo& d : devices)
        out += (out.empty() ? "" : ", ") + std::to_string(d.index) + " " + d.name;
    return out;
}

bool isLavapipe(const VulkanDeviceInfo& info) {
    return info.type == "cpu" || info.name.rfind("llvmpipe", 0) == 0;
}

/// A validation message on one line (the layer's own messages carry newlines).
std::string oneLine(const char* text) {
    std::string s = text ? text : "";
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

} // namespace

void VulkanContext::check(VkResult result, const char* what) {
    if (result != VK_SUCCESS)
        throw Error(std::string("vulkan: ") + what + " failed: " + resultName(result), ExitCode::Failure);
}

namespace {

/// The chosen driver's lavapipe, loaded once and kept (the Vulkan loader then gets the same handle), so
/// that one that cannot load is refused in one line naming it (core/DriverTable.h).
void requireDriverLoadable() {
    const std::string library = DriverTable::libraryToLoad(DriverTable::Api::Vulkan);
    if (!library.empty() && !::dlopen(library.c_str(), RTLD_LAZY | RTLD_LOCAL))
        throw DriverTable::cannotLoad(DriverTable::Api::Vulkan, ::dlerror());
}

} // namespace

std::vector<VulkanDeviceInfo> VulkanContext::listDevices() {
    requireDriverLoadable();
    VkInstance instance = createBareInstance();
    pinVulkanLibraries();
    std::vector<VulkanDeviceInfo> out;
    try {
        std::vector<VkPhysicalDevice> devices = physicalDevices(instance);
        for (size_t i = 0; i < devices.size(); ++i) out.push_back(describe(devices[i], static_cast<int>(i)));
    } catch (...) {
        vkDestroyInstance(instance, nullptr);
        throw;
    }
    vkDestroyInstance(instance, nullptr);
    return out;
}

VulkanContext::VulkanContext(const VulkanOptions& options) {
    try {
        requireDriverLoadable();
        createInstance(options.validation);
        pinVulkanLibraries();
        pickDevice(options.device);
        createDevice();
    } catch (...) {
        // The destructor does not run for a throwing constructor; release what was created.
        destroy();
        throw;
    }
}

VulkanContext::~VulkanContext() {
    destroy();
}

void VulkanContext::destroy() {
    if (mDevice) {
        vkDeviceWaitIdle(mDevice);
        if (mCommandPool) vkDestroyCommandPool(mDevice, mCommandPool, nullptr);
        vkDestroyDevice(mDevice, nullptr);
    }
    mCommandPool = VK_NULL_HANDLE;
    mDevice = VK_NULL_HANDLE;
    if (mMessenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(mInstance, mMessenger, nullptr);
    }
    mMessenger = VK_NULL_HANDLE;
    if (mInstance) vkDestroyInstance(mInstance, nullptr);
    mInstance = VK_NULL_HANDLE;
}

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                        VkDebugUtilsMessageTypeFlagsEXT,
                                                        const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                        void* self) {
    auto* context = static_cast<VulkanContext*>(self);
    const bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
    context->mMessages.push_back(std::string(error ? "error: " : "warning: ") + oneLine(data->pMessage));
    if (error) ++context->mErrors;
    return VK_FALSE; // never abort the call
}

void VulkanContext::clearValidationMessages() {
    mMessages.clear();
    mErrors = 0;
}

void VulkanContext::createInstance(bool validation) {
    DriverShaderCache::separateByVectorWidth(); // before lavapipe opens its shader cache
    if (!validation) {
        mInstance = createBareInstance();
        return;
    }
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    if (count) vkEnumerateInstanceLayerProperties(&count, layers.data());
    bool found = false;
    for (uint32_t i = 0; i < count; ++i) found |= std::strcmp(layers[i].layerName, kValidationLayer) == 0;
    if (!found)
        throw Error(std::string("vulkan: validation layer ") + kValidationLayer +
                        " not installed (install the Debian package vulkan-validationlayers)",
                    ExitCode::Unsupported);

    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &VulkanContext::onMessage;
    messenger.pUserData = this;

    const char* layerNames[] = {kValidationLayer};
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "shadowbench";
    app.apiVersion = instanceApiVersion();
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = &messenger; // covers vkCreateInstance and vkDestroyInstance themselves
    info.pApplicationInfo = &app;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layerNames;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
    VkResult result = vkCreateInstance(&info, nullptr, &mInstance);
    if (result != VK_SUCCESS) {
        mInstance = VK_NULL_HANDLE;
        instanceFailed(result);
    }
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(mInstance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw Error("vulkan: vkCreateDebugUtilsMessengerEXT not found", ExitCode::Failure);
    check(create(mInstance, &messenger, nullptr, &mMessenger), "vkCreateDebugUtilsMessengerEXT");
}

void VulkanContext::pickDevice(int index) {
    std::vector<VkPhysicalDevice> devices = physicalDevices(mInstance);
    std::vector<VulkanDeviceInfo> infos;
    for (size_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], static_cast<int>(i)));
    int chosen = 0;
    if (index >= 0) {
        if (index >= static_cast<int>(devices.size()))
            throw Error("vulkan: --vk-device " + std::to_string(index) +
                            ": out of range (devices: " + deviceList(infos) + ")",
                        ExitCode::BadInput);
        chosen = index;
    } else {
        for (size_t i = 0; i < infos.size(); ++i)
            if (isLavapipe(infos[i])) {
                chosen = static_cast<int>(i);
                break;
            }
    }
    mPhysical = devices[chosen];
    mInfo = describe(mPhysical, chosen, &mProperties);
    uint32_t extensions = 0;
    vkEnumerateDeviceExtensionProperties(mPhysical, nullptr, &extensions, nullptr);
    std::vector<VkExtensionProperties> offered(extensions);
    vkEnumerateDeviceExtensionProperties(mPhysical, nullptr, &extensions, offered.data());
    for (const VkExtensionProperties& e : offered) mDeviceExtensions.emplace_back(e.extensionName);
}

std::vector<std::string> VulkanContext::missingRayQueryExtensions() const {
    std::vector<std::string> missing;
    for (const char* name : kRayQueryExtensions)
        if (!hasDeviceExtension(name)) missing.emplace_back(name);
    return missing;
}

bool VulkanContext::offersRayQuery() {
    mMissingRayQueryFeatures.clear();
    // The Vulkan 1.2 features structure (bufferDeviceAddress) exists from a 1.2 device on.
    if (!missingRayQueryExtensions().empty() || mProperties.apiVersion < VK_API_VERSION_1_2) return false;
    VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR structures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    structures.pNext = &rayQuery;
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    vulkan12.pNext = &structures;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &vulkan12;
    vkGetPhysicalDeviceFeatures2(mPhysical, &features);
    if (!structures.accelerationStructure) mMissingRayQueryFeatures.emplace_back("accelerationStructure");
    if (!rayQuery.rayQuery) mMissingRayQueryFeatures.emplace_back("rayQuery");
    if (!vulkan12.bufferDeviceAddress) mMissingRayQueryFeatures.emplace_back("bufferDeviceAddress");
    return mMissingRayQueryFeatures.empty();
}

bool VulkanContext::offersMeshShader() {
    mMeshProperties = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_PROPERTIES_EXT};
    if (!hasDeviceExtension(VK_EXT_MESH_SHADER_EXTENSION_NAME) || mProperties.apiVersion < VK_API_VERSION_1_2)
        return false;
    VkPhysicalDeviceMeshShaderFeaturesEXT mesh{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &mesh;
    vkGetPhysicalDeviceFeatures2(mPhysical, &features);
    if (!mesh.meshShader) return false;
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &mMeshProperties;
    vkGetPhysicalDeviceProperties2(mPhysical, &properties);
    mMeshProperties.pNext = nullptr;
    return true;
}

bool VulkanContext::hasDeviceExtension(const std::string& name) const {
    return std::find(mDeviceExtensions.begin(), mDeviceExtensions.end(), name) != mDeviceExtensions.end();
}

void VulkanContext::createDevice() {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(mPhysical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(mPhysical, &count, families.data());
    bool found = false;
    for (uint32_t i = 0; i < count && !found; ++i)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
            mQueueFamily = i;
            found = true;
        }
    if (!found)
        throw Error("vulkan: device '" + mInfo.name + "' has no graphics queue", ExitCode::Unsupported);

    VkPhysicalDeviceFeatures available{};
    vkGetPhysicalDeviceFeatures(mPhysical, &available);
    VkPhysicalDeviceFeatures enabled{};
    enabled.depthClamp = available.depthClamp;
    enabled.pipelineStatisticsQuery = available.pipelineStatisticsQuery;
    enabled.geometryShader = available.geometryShader; // GraphicsPipelineDesc::geometry (volume extrusion)
    // volume's extrusion=geometry: its geometry shader adds the triangles it emits to a storage buffer
    // (enabled wherever offered: VolumeVulkan asks the physical device)
    enabled.vertexPipelineStoresAndAtomics = available.vertexPipelineStoresAndAtomics;
    enabled.imageCubeArray = available.imageCubeArray; // samplerCubeArrayShadow (cubemap's lighting pass)
    // gl_ClipDistance: paraboloid's cut at each half's plane, occluder's bake (one side of the
    // cross-section's plane) and planar's guards
    enabled.shaderClipDistance = available.shaderClipDistance;
    // volume's light pass blends colour ADD and visibility MAX, as GL's per-draw-buffer equations do
    enabled.independentBlend = available.independentBlend;
    // volume's depth_bounds (GL_EXT_depth_bounds_test) and its stencil_samples_passed counter
    // (GL_SAMPLES_PASSED counts samples; a Vulkan occlusion query counts them only with the precise bit)
    enabled.depthBounds = available.depthBounds;
    enabled.occlusionQueryPrecise = available.occlusionQueryPrecise;
    // raytraced's ray counter: one atomic add per fragment that traced (techniques/raytraced/)
    enabled.fragmentStoresAndAtomics = available.fragmentStoresAndAtomics;
    mFragmentStoresAndAtomics = available.fragmentStoresAndAtomics == VK_TRUE;
    // virtual's path=sparse: its map one sparse-resident image (techniques/virtual/VirtualVulkan.h)
    enabled.sparseBinding = available.sparseBinding;
    enabled.sparseResidencyImage2D = available.sparseResidencyImage2D;
    mSparseResidency = available.sparseBinding == VK_TRUE && available.sparseResidencyImage2D == VK_TRUE;
    mDepthBounds = available.depthBounds == VK_TRUE;
    mOcclusionQueryPrecise = available.occlusionQueryPrecise == VK_TRUE;
    mDepthClamp = available.depthClamp == VK_TRUE;
    mIndependentBlend = available.independentBlend == VK_TRUE;
    mClipDistance = available.shaderClipDistance == VK_TRUE;
    mPipelineStatistics = available.pipelineStatisticsQuery == VK_TRUE;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = mQueueFamily;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.pEnabledFeatures = &enabled;
    // Ray queries and mesh shaders: the extensions and a features chain, each only where the device
    // offers all of it (with a chain, the core features travel in VkPhysicalDeviceFeatures2 instead of
    // pEnabledFeatures). A device offering neither is created exactly as before.
    mRayQuery = offersRayQuery();
    mMeshShader = offersMeshShader();
    std::vector<const char*> extensions;
    VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR structures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceMeshShaderFeaturesEXT mesh{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT};
    VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features2.features = enabled;
    void** tail = &features2.pNext; // where the next structure of the chain goes
    if (mRayQuery) {
        rayQuery.rayQuery = VK_TRUE;
        structures.accelerationStructure = VK_TRUE;
        structures.pNext = &rayQuery;
        vulkan12.bufferDeviceAddress = VK_TRUE;
        vulkan12.pNext = &structures;
        *tail = &vulkan12;
        tail = &rayQuery.pNext;
        extensions.assign(kRayQueryExtensions.begin(), kRayQueryExtensions.end());
    }
    if (mMeshShader) { // volume's extrusion=mesh: the mesh stage only (no task shader is used)
        mesh.meshShader = VK_TRUE;
        *tail = &mesh;
        tail = &mesh.pNext;
        extensions.push_back(VK_EXT_MESH_SHADER_EXTENSION_NAME);
    }
    if (features2.pNext) {
        info.pNext = &features2;
        info.pEnabledFeatures = nullptr;
        info.enabledExtensionCount = uint32_t(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
    }
    check(vkCreateDevice(mPhysical, &info, nullptr, &mDevice), "vkCreateDevice");
    vkGetDeviceQueue(mDevice, mQueueFamily, 0, &mQueue);
    if (mRayQuery) mRayQueryFunctions = RayQueryFunctions::load(mDevice);
    if (mMeshShader) {
        mCmdDrawMeshTasks = reinterpret_cast<PFN_vkCmdDrawMeshTasksEXT>(
            vkGetDeviceProcAddr(mDevice, "vkCmdDrawMeshTasksEXT"));
        if (!mCmdDrawMeshTasks)
            throw Error("vulkan: device '" + mInfo.name +
                            "' offers VK_EXT_mesh_shader but returns no "
                            "vkCmdDrawMeshTasksEXT",
                        ExitCode::Failure);
    }

    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = mQueueFamily;
    check(vkCreateCommandPool(mDevice, &pool, nullptr, &mCommandPool), "vkCreateCommandPool");

    mTimestampPeriodNs =
        families[mQueueFamily].timestampValidBits == 0 ? 0.0 : double(mProperties.limits.timestampPeriod);
}

uint32_t VulkanContext::memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const {
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(mPhysical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw Error("vulkan: no memory type with properties 0x" + std::to_string(flags) + " on '" + mInfo.name +
                    "'",
                ExitCode::Failure);
}

VkFormat VulkanContext::depthStencilFormat() const {
    const VkFormatFeatureFlags need =
        VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    for (VkFormat format : {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT}) {
        VkFormatProperties props{};
        vkGetPhysicalDeviceFormatProperties(mPhysical, format, &props);
        if ((props.optimalTilingFeatures & need) == need) return format;
    }
    throw Error("vulkan: device '" + mInfo.name + "' has no depth-stencil format (D24S8 or D32S8)",
                ExitCode::Unsupported);
}

void VulkanContext::submitNow(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = mCommandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(mDevice, &alloc, &cmd), "vkAllocateCommandBuffers");
    VkFence fence = VK_NULL_HANDLE;
    auto cleanup = [&] {
        if (fence) vkDestroyFence(mDevice, fence, nullptr);
        vkFreeCommandBuffers(mDevice, mCommandPool, 1, &cmd);
    };
    try {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
        record(cmd);
        check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        check(vkCreateFence(mDevice, &fenceInfo, nullptr, &fence), "vkCreateFence");
        submit(cmd, fence);
        check(vkWaitForFences(mDevice, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    } catch (...) {
        cleanup();
        throw;
    }
    cleanup();
}

void VulkanContext::submit(VkCommandBuffer cmd, VkFence fence) {
    VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    info.commandBufferCount = 1;
    info.pCommandBuffers = &cmd;
    check(vkQueueSubmit(mQueue, 1, &info, fence), "vkQueueSubmit");
}

uint32_t VulkanContext::uniformStride(VkDeviceSize bytes) const {
    const VkDeviceSize align = mProperties.limits.minUniformBufferOffsetAlignment;
    return uint32_t((bytes + align - 1) / align * align);
}

} // namespace sb
