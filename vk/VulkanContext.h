#pragma once
// The Vulkan platform (docs/ARCHITECTURE.md, "Layout": vk/): one instance, one physical device, one
// logical device with a graphics queue, and a command pool, for headless rendering (no surface, no
// swapchain). It is to the Vulkan back end what gl/Context is to the GL one, and it knows nothing of
// scenes or techniques.
//
// Device choice: by default Mesa's lavapipe (the llvmpipe device, the software rasteriser GL runs on,
// so GL and Vulkan compare on the same gallivm back end), else the first device; `device` picks one by
// index in vkEnumeratePhysicalDevices order (`bench --api vulkan --vk-device N`, listed by
// `bench --list`).
//
// Errors: no Vulkan loader, no ICD or no device is ExitCode::Unsupported (the machine lacks it); an
// index out of range is ExitCode::BadInput (the input is wrong), naming the devices there are.
//
// Ray queries (techniques/raytraced/): VK_KHR_acceleration_structure, VK_KHR_ray_query and
// VK_KHR_deferred_host_operations (which acceleration structures require), with the features
// accelerationStructure, rayQuery and bufferDeviceAddress (Vulkan 1.2's features), are enabled only where the
// device offers every one of them (lavapipe of Mesa 25.0.7 does, 22.3.6 does not): a device without them
// is created exactly as before, so no other technique runs on a device configured differently. rayQuery()
// says whether they are on, and then rayQueryFunctions() holds the extension's entry points.
//
// Mesh shaders (volume's extrusion=mesh): VK_EXT_mesh_shader with its meshShader feature, enabled only
// where the device offers both (lavapipe of Mesa 25.0.7 does, 22.3.6 does not), as ray queries are;
// meshShader() says whether it is on, meshShaderProperties() holds the device's limits and
// cmdDrawMeshTasks() the draw (vkCmdDrawMeshTasksEXT, fetched from the device).
//
// Validation: with `validation` on, the Khronos validation layer (VK_LAYER_KHRONOS_validation) is enabled
// and a VK_EXT_debug_utils messenger records every message of severity warning or error. Tests run with
// it on and require validationErrors() == 0; timed runs leave it off (the layer's checks would be
// measured). A requested layer that is not installed is ExitCode::Unsupported.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/RayQueryFunctions.h"

namespace sb {

struct VulkanOptions {
    int device = -1;         ///< index into the physical devices; -1: lavapipe, else the first
    bool validation = false; ///< Khronos validation layer and the message log
};

/// One physical device as `bench --list` shows it.
struct VulkanDeviceInfo {
    int index = 0;
    std::string name;       ///< VkPhysicalDeviceProperties::deviceName ("llvmpipe (LLVM 15.0.6, 256 bits)")
    std::string type;       ///< "cpu", "integrated", "discrete", "virtual", "other"
    std::string driver;     ///< driverName and driverInfo ("llvmpipe Mesa 22.3.6 (LLVM 15.0.6)")
    std::string driverInfo; ///< driverInfo alone, the driver's version ("Mesa 22.3.6 (LLVM 15.0.6)")
    std::string apiVersion; ///< "1.3.230"
};

class VulkanContext {
public:
    /// Creates instance, device, queue and command pool. Throws sb::Error as described above.
    explicit VulkanContext(const VulkanOptions& options);
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    /// The devices the loader sees, without creating a device. Throws ExitCode::Unsupported when there is
    /// no loader or no device.
    static std::vector<VulkanDeviceInfo> listDevices();

    VkInstance instance() const { return mInstance; }
    VkPhysicalDevice physicalDevice() const { return mPhysical; }
    VkDevice device() const { return mDevice; }
    VkQueue queue() const { return mQueue; }
    uint32_t queueFamily() const { return mQueueFamily; }
    VkCommandPool commandPool() const { return mCommandPool; }
    const VulkanDeviceInfo& info() const { return mInfo; }
    const VkPhysicalDeviceProperties& properties() const { return mProperties; }
    /// `bytes` rounded up to minUniformBufferOffsetAlignment: the stride of consecutive slots of a
    /// dynamic uniform buffer, each bound at its own offset.
    uint32_t uniformStride(VkDeviceSize bytes) const;
    /// Nanoseconds per timestamp tick; 0 when the queue writes no timestamps (timestampValidBits 0).
    double timestampPeriodNs() const { return mTimestampPeriodNs; }
    /// Whether depthClamp (volume's closed far cap) and the other features used were enabled.
    bool depthClamp() const { return mDepthClamp; }
    bool pipelineStatistics() const { return mPipelineStatistics; }
    /// Blend state per colour attachment (volume's light pass: colour ADD, visibility MAX).
    bool independentBlend() const { return mIndependentBlend; }
    /// gl_ClipDistance in shaders (planar's guards clip occluder parts behind the receiver).
    bool clipDistance() const { return mClipDistance; }
    /// The depth bounds test (volume's depth_bounds); lavapipe 22.3.6 and 25.0.7 lack it.
    bool depthBounds() const { return mDepthBounds; }
    /// Occlusion queries that count samples, not only zero or non-zero (volume's stencil_samples_passed).
    bool occlusionQueryPrecise() const { return mOcclusionQueryPrecise; }
    /// Fragment-stage stores and atomics (raytraced's exact ray counter).
    bool fragmentStoresAndAtomics() const { return mFragmentStoresAndAtomics; }
    /// sparseBinding and sparseResidencyImage2D, both enabled (virtual's path=sparse).
    bool sparseResidency() const { return mSparseResidency; }
    /// Whether ray queries are on: the three extensions and three features above, all enabled.
    bool rayQuery() const { return mRayQuery; }
    /// The acceleration-structure entry points; every pointer is null unless rayQuery().
    const RayQueryFunctions& rayQueryFunctions() const { return mRayQueryFunctions; }
    /// The device extensions ray queries need (kRayQueryExtensions) that the physical device lacks, in
    /// that order; empty where it offers them all.
    std::vector<std::string> missingRayQueryExtensions() const;
    /// The features ray queries need that the device lacks although it offers the extensions
    /// ("accelerationStructure", "rayQuery", "bufferDeviceAddress"); empty where it has them all.
    const std::vector<std::string>& missingRayQueryFeatures() const { return mMissingRayQueryFeatures; }
    /// Whether VK_EXT_mesh_shader and its meshShader feature are on (the device offers both).
    bool meshShader() const { return mMeshShader; }
    /// The device's mesh shader limits (zeroed unless meshShader()).
    const VkPhysicalDeviceMeshShaderPropertiesEXT& meshShaderProperties() const { return mMeshProperties; }
    /// vkCmdDrawMeshTasksEXT; null unless meshShader().
    PFN_vkCmdDrawMeshTasksEXT cmdDrawMeshTasks() const { return mCmdDrawMeshTasks; }
    /// Whether the physical device offers device extension `name` ("VK_KHR_ray_query").
    bool hasDeviceExtension(const std::string& name) const;

    /// A memory type index with `bits` allowed and `flags` set. Throws sb::Error(Failure) when none.
    uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const;
    /// A depth-stencil format the device can attach and sample: D24_UNORM_S8_UINT, else D32_SFLOAT_S8_UINT.
    VkFormat depthStencilFormat() const;

    /// Records `record` into a fresh primary command buffer, submits it and waits (uploads, readbacks,
    /// layout changes outside frames). Throws sb::Error(Failure) on a failed submit.
    void submitNow(const std::function<void(VkCommandBuffer)>& record);
    /// Submits `cmd` and signals `fence` (the frame's submit).
    void submit(VkCommandBuffer cmd, VkFence fence);

    /// Validation messages recorded so far (severity warning and error), "error: <message>" or
    /// "warning: <message>", oldest first; empty without validation.
    const std::vector<std::string>& validationMessages() const { return mMessages; }
    size_t validationErrors() const { return mErrors; }
    bool validationEnabled() const { return mMessenger != VK_NULL_HANDLE; }
    /// Forgets the messages recorded so far (a test that provoked one on purpose).
    void clearValidationMessages();

    /// Throws sb::Error(Failure) naming `what` and the VkResult when `result` is not VK_SUCCESS.
    static void check(VkResult result, const char* what);

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                    VkDebugUtilsMessageTypeFlagsEXT types,
                                                    const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                    void* self);
    void createInstance(bool validation);
    void pickDevice(int index);
    void createDevice();
    /// Whether the device offers every extension and feature of ray queries (fills
    /// mMissingRayQueryFeatures); false without querying features where an extension is missing.
    bool offersRayQuery();
    /// Whether the device offers VK_EXT_mesh_shader with the meshShader feature (fills mMeshProperties).
    bool offersMeshShader();
    void destroy(); ///< releases whatever was created (the destructor, and a constructor that throws)

    VkInstance mInstance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT mMessenger = VK_NULL_HANDLE;
    VkPhysicalDevice mPhysical = VK_NULL_HANDLE;
    VkDevice mDevice = VK_NULL_HANDLE;
    VkQueue mQueue = VK_NULL_HANDLE;
    uint32_t mQueueFamily = 0;
    VkCommandPool mCommandPool = VK_NULL_HANDLE;
    VulkanDeviceInfo mInfo;
    VkPhysicalDeviceProperties mProperties{};
    double mTimestampPeriodNs = 0.0;
    bool mDepthClamp = false;
    bool mPipelineStatistics = false;
    bool mIndependentBlend = false;
    bool mClipDistance = false;
    bool mDepthBounds = false;
    bool mOcclusionQueryPrecise = false;
    bool mFragmentStoresAndAtomics = false;
    bool mSparseResidency = false;
    bool mRayQuery = false;
    RayQueryFunctions mRayQueryFunctions;
    bool mMeshShader = false;
    VkPhysicalDeviceMeshShaderPropertiesEXT mMeshProperties{};
    PFN_vkCmdDrawMeshTasksEXT mCmdDrawMeshTasks = nullptr;
    std::vector<std::string> mMissingRayQueryFeatures;
    std::vector<std::string> mMessages;
    size_t mErrors = 0;
    std::vector<std::string> mDeviceExtensions; ///< what the physical device offers (pickDevice)
};

} // namespace sb
