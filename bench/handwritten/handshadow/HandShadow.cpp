// handshadow: a shadow-mapping program written the way a small demo would write it, sharing no harness
// code with bench: its own EGL surfaceless context, its own GLSL programs (string literals below), its
// own buffers, targets and draw loop. It exists to say how fast a lean shadow map is on this machine, so
// that `bench -t shadowmap` can be held against it (scripts/handshadow.sh, results/ci/lean-shadow-pass.md).
//
// From scenes/ and core/ it takes only what makes both programs draw the same triangles: the scene and
// model loader, the camera preset's matrices and the light camera fitted to the casters
// (scenes/LightFit.h, the one `shadowmap` uses). The frame:
//   1. depth pass into a GL_DEPTH_COMPONENT24 texture (--map-size, default 2x the output's larger side),
//      the casters only, glPolygonOffset(2, 2) as bench's defaults;
//   2. lit pass into an RGBA8 colour texture + DEPTH24 renderbuffer: Lambert + ambient, the map read
//      through a depth-compare sampler with bilinear filtering (bench's hardware_compare=true, pcf=1).
//      --harness-targets renders into bench's target layout instead (RGBA16F visibility written too,
//      DEPTH24_STENCIL8), so that a comparison can tell the harness contract's cost from the technique's.
// Timing per frame: CPU submit (first GL call to the last) and wall (submit + glFinish); the median of
// each over --frames after --warmup is printed, with one `csv,` line for scripts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "core/PngFile.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {
using Clock = std::chrono::steady_clock;

struct Options {
    std::string scene = "aircraft";
    std::string model;
    int instances = -1;
    std::string camera = "far";
    int width = 1024, height = 1024;
    int mapSize = 0; ///< 0: twice the output's larger side
    int frames = 50, warmup = 5;
    std::string png;
    bool harnessTargets = false; ///< --harness-targets: bench's FrameTargets layout instead of colour + depth
};

const char* kUsage =
    "usage: handshadow [--scene NAME|FILE] [--model FILE] [--instances N] [--camera NAME] [--size WxH]\n"
    "                  [--map-size N] [--frames N] [--warmup N] [--png FILE] [--harness-targets]\n"
    "--harness-targets: render into bench's target layout (RGBA8 colour, RGBA16F visibility written by\n"
    "the lit pass, DEPTH24_STENCIL8) instead of a demo's RGBA8 colour + DEPTH24, to tell the technique's\n"
    "cost from the harness contract's in a comparison.\n";

int toInt(const std::string& option, const std::string& v) {
    char* end = nullptr;
    long x = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || x < 0 || x > 1000000)
        throw Error("handshadow: " + option + ": expected a non-negative integer, got \"" + v + "\"");
    return int(x);
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "-h" || a == "--help") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        }
        if (a == "--harness-targets") {
            o.harnessTargets = true;
            continue;
        }
        if (i + 1 >= argc) throw Error("handshadow: " + a + ": unknown option or missing value");
        std::string v = argv[++i];
        if (a == "--scene")
            o.scene = v;
        else if (a == "--model")
            o.model = v;
        else if (a == "--instances" || a == "-n")
            o.instances = toInt(a, v);
        else if (a == "--camera")
            o.camera = v;
        else if (a == "--map-size")
            o.mapSize = toInt(a, v);
        else if (a == "--frames")
            o.frames = std::max(1, toInt(a, v));
        else if (a == "--warmup")
            o.warmup = toInt(a, v);
        else if (a == "--png")
            o.png = v;
        else if (a == "--size") {
            if (std::sscanf(v.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1 ||
                o.width > 16384 || o.height > 16384)
                throw Error("handshadow: --size: expected WIDTHxHEIGHT, got \"" + v + "\"");
        } else
            throw Error("handshadow: " + a + ": unknown option");
    }
    if (o.mapSize == 0) o.mapSize = 2 * std::max(o.width, o.height);
    if (o.mapSize < 16 || o.mapSize > 16384)
        throw Error("handshadow: --map-size: expected 16 to 16384, got " + std::to_string(o.mapSize));
    return o;
}

// ---- the sanitizer build --------------------------------------------------------------------------
// GCC says __SANITIZE_ADDRESS__; clang 14 (the asan preset) says __has_feature(address_sanitizer).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SB_ADDRESS_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(SB_ADDRESS_SANITIZER)
/// LeakSanitizer is off for this program alone; AddressSanitizer and UBSan still check every access.
/// Why: LSan's stop-the-world tracer crashed at handshadow's exit on the CI machine in two of two runs
/// ("Tracer caught signal 11", exit 1, after all frames and the image were right), a fault inside the
/// sanitizer runtime that 72 runs here never reproduced (cold and warm shader cache, LP_NUM_THREADS 2 to
/// 32) and that bench, leak-checked in every CLI test with the same driver and the same threads alive at
/// exit, never showed. handshadow allocates nothing that outlives its frames but the driver's state, and
/// a leak check of the driver is not what this measuring program is for. This is the runtime's
/// documented per-program switch, declared in its public interface header.
extern "C" int __lsan_is_turned_off() {
    return 1;
}
#endif

// ---- the context: EGL on Mesa's surfaceless platform, no window, no pbuffer ----------------------
/// The EGL context, destroyed before exit as bench's EGL backend does (gl/backends/EglContext.cpp), so
/// that both programs leave the driver the same way. No eglTerminate, like bench: it unloads the driver,
/// and the driver's per-process allocations would then be reported as leaks from an unknown module.
/// (Destroying the context does not join llvmpipe's threads: in Mesa 22.3 the rasteriser, compute and
/// disk-cache threads belong to the screen and are alive at exit in bench and here alike, seen in gdb.)
struct EglSession {
    EGLDisplay dpy = EGL_NO_DISPLAY;
    EGLContext ctx = EGL_NO_CONTEXT;
    EglSession() = default;
    EglSession(const EglSession&) = delete;
    EglSession& operator=(const EglSession&) = delete;
    ~EglSession() {
        if (dpy == EGL_NO_DISPLAY) return;
        eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (ctx != EGL_NO_CONTEXT) eglDestroyContext(dpy, ctx);
    }
};

void createContext(EglSession& session) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay)
        throw Error("handshadow: eglGetPlatformDisplayEXT is missing", ExitCode::Unsupported);
    EGLDisplay dpy = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr))
        throw Error("handshadow: no EGL surfaceless display (EGL_MESA_platform_surfaceless)",
                    ExitCode::Unsupported);
    session.dpy = dpy;
    if (!eglBindAPI(EGL_OPENGL_API))
        throw Error("handshadow: eglBindAPI(OpenGL) failed", ExitCode::Unsupported);
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    eglChooseConfig(dpy, configAttribs, &config, 1, &count);
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext ctx =
        eglCreateContext(dpy, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctxAttribs);
    session.ctx = ctx;
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
        throw Error("handshadow: no GL 4.5 core context on the surfaceless display", ExitCode::Unsupported);
}

// ---- programs ----------------------------------------------------------------------------------
const char* kDepthVert = R"(#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;
layout(location = 8) uniform mat4 uLightViewProj;
void main() { gl_Position = uLightViewProj * (uModel * vec4(aPosition, 1.0)); }
)";
const char* kDepthFrag = R"(#version 450 core
void main() {}
)";
const char* kLitVert = R"(#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 0) uniform mat4 uModel;
layout(location = 4) uniform vec3 uColor;
layout(location = 5) uniform mat4 uViewProj;
layout(location = 9) uniform mat4 uShadowMatrix;
out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vShadowCoord;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(uModel) * aNormal;
    vShadowCoord = uShadowMatrix * world;
    gl_Position = uViewProj * world;
}
)";
// One light, as bench's lighting.glsl: directional (w = 0) or spot (w = 2) with cone and range.
const char* kLitFrag = R"(#version 450 core
in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vShadowCoord;
layout(location = 4) uniform vec3 uColor;
layout(location = 13) uniform vec4 uLightPos;    // xyz position, w type
layout(location = 14) uniform vec4 uLightDir;    // xyz direction, w cos(outer)
layout(location = 15) uniform vec4 uLightColor;  // rgb colour * intensity, w range
layout(location = 16) uniform vec4 uAmbientInner; // rgb ambient, w cos(inner)
layout(binding = 0) uniform sampler2DShadow uShadowMap;
layout(location = 0) out vec4 oColor;
#ifdef VISIBILITY
layout(location = 1) out vec4 oVisibility;
#endif
void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 l = uLightPos.w == 0.0 ? -uLightDir.xyz : normalize(uLightPos.xyz - vWorldPos);
    float atten = 1.0;
    if (uLightPos.w != 0.0) {
        if (uLightColor.w > 0.0) atten = clamp(1.0 - length(uLightPos.xyz - vWorldPos) / uLightColor.w, 0.0, 1.0);
        if (uLightPos.w == 2.0) atten *= smoothstep(uLightDir.w, uAmbientInner.w, dot(-l, uLightDir.xyz));
    }
    float vis = 1.0;
    if (vShadowCoord.w > 0.0) {
        vec3 p = vShadowCoord.xyz / vShadowCoord.w;
        if (all(greaterThanEqual(p.xy, vec2(0.0))) && all(lessThanEqual(p.xy, vec2(1.0))) && p.z <= 1.0)
            vis = texture(uShadowMap, p);
    }
    vec3 light = uAmbientInner.rgb + vis * uLightColor.rgb * (max(dot(n, l), 0.0) * atten);
    oColor = vec4(uColor * light, 1.0);
#ifdef VISIBILITY
    oVisibility = vec4(vis, 1.0, 1.0, 1.0);
#endif
}
)";

GLuint compile(const char* vs, const char* fs, const char* what) {
    GLuint p = glCreateProgram();
    for (auto [type, src] : {std::pair{GL_VERTEX_SHADER, vs}, std::pair{GL_FRAGMENT_SHADER, fs}}) {
        GLuint s = glCreateShader(type);
        glShaderSource(s, 1, &src, nullptr);
        glCompileShader(s);
        GLint ok = 0;
        glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[2048];
            glGetShaderInfoLog(s, sizeof log, nullptr, log);
            throw Error(std::string("handshadow: ") + what + " shader: " + log, ExitCode::Failure);
        }
        glAttachShader(p, s);
        glDeleteShader(s);
    }
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) throw Error(std::string("handshadow: ") + what + " program does not link", ExitCode::Failure);
    return p;
}

struct MeshGpu {
    GLuint vao = 0;
    GLsizei count = 0;
};

std::vector<MeshGpu> upload(const Scene& scene) {
    std::vector<MeshGpu> out;
    for (const Mesh& m : scene.meshes) {
        std::vector<float> v;
        v.reserve(m.positions.size() * 6);
        for (size_t i = 0; i < m.positions.size(); ++i)
            v.insert(v.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z, m.normals[i].x,
                               m.normals[i].y, m.normals[i].z});
        GLuint vao, buf[2];
        glCreateVertexArrays(1, &vao);
        glCreateBuffers(2, buf);
        glNamedBufferStorage(buf[0], GLsizeiptr(v.size() * sizeof(float)), v.data(), 0);
        glNamedBufferStorage(buf[1], GLsizeiptr(m.indices.size() * 4), m.indices.data(), 0);
        glVertexArrayVertexBuffer(vao, 0, buf[0], 0, 24);
        glVertexArrayElementBuffer(vao, buf[1]);
        for (GLuint a : {0u, 1u}) {
            glEnableVertexArrayAttrib(vao, a);
            glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, a * 12);
            glVertexArrayAttribBinding(vao, a, 0);
        }
        out.push_back({vao, GLsizei(m.indices.size())});
    }
    return out;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void writePng(const std::string& path, int w, int h) {
    std::vector<unsigned char> px(size_t(w) * size_t(h) * 3); // RGB, as bench --screenshot writes
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, px.data());
    // GL rows are bottom-up; a negative stride writes them top-down.
    const std::ptrdiff_t row = std::ptrdiff_t(w) * 3;
    try {
        PngFile::write(path, w, h, 3, px.data() + size_t(h - 1) * size_t(row), -row);
    } catch (const Error& e) {
        throw Error(std::string("handshadow: --png: ") + e.what(), ExitCode::Failure);
    }
}
} // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parseOptions(argc, argv);
        SceneOptions so;
        if (o.instances >= 0) so.instances = uint32_t(o.instances);
        so.modelPath = o.model;
        Scene scene = SceneLoader::load(o.scene, so);
        const CameraPreset* cam = scene.findCamera(o.camera);
        if (!cam)
            throw Error("handshadow: --camera: scene " + scene.name + " has no camera \"" + o.camera + "\"");
        if (scene.lights.empty()) throw Error("handshadow: scene " + scene.name + " has no light");
        const Light& light = scene.lights[0];
        if (light.type == LightType::Point)
            throw Error("handshadow: a point light needs a cube map; this program does one 2D map");

        EglSession session;
        createContext(session);
        const glm::mat4 viewProj =
            cameraProjection(*cam, float(o.width) / float(o.height)) * cameraView(*cam);
        const glm::mat4 lightViewProj = fitLightViewProjection(scene, light);
        const glm::mat4 toTexture =
            glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
        const glm::mat4 shadowMatrix = toTexture * lightViewProj;

        const GLuint depthProgram = compile(kDepthVert, kDepthFrag, "depth");
        std::string litFrag = kLitFrag;
        if (o.harnessTargets) litFrag.insert(litFrag.find('\n') + 1, "#define VISIBILITY\n");
        const GLuint litProgram = compile(kLitVert, litFrag.c_str(), "lit");
        const std::vector<MeshGpu> meshes = upload(scene);

        // The shadow map: a depth texture, compare mode on, bilinear (four compares filtered).
        GLuint map, mapFbo;
        glCreateTextures(GL_TEXTURE_2D, 1, &map);
        glTextureStorage2D(map, 1, GL_DEPTH_COMPONENT24, o.mapSize, o.mapSize);
        glTextureParameteri(map, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(map, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(map, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(map, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(map, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTextureParameteri(map, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glCreateFramebuffers(1, &mapFbo);
        glNamedFramebufferTexture(mapFbo, GL_DEPTH_ATTACHMENT, map, 0);
        glNamedFramebufferDrawBuffer(mapFbo, GL_NONE);
        glNamedFramebufferReadBuffer(mapFbo, GL_NONE);

        // The output: RGBA8 colour + a depth renderbuffer, nothing else. With --harness-targets, bench's
        // layout (gl/FrameTargets.h): an RGBA16F visibility texture too, and depth with stencil.
        GLuint colour, visibility = 0, depth, fbo;
        glCreateTextures(GL_TEXTURE_2D, 1, &colour);
        glTextureStorage2D(colour, 1, GL_RGBA8, o.width, o.height);
        glCreateRenderbuffers(1, &depth);
        glNamedRenderbufferStorage(depth, o.harnessTargets ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24,
                                   o.width, o.height);
        glCreateFramebuffers(1, &fbo);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, colour, 0);
        glNamedFramebufferRenderbuffer(fbo,
                                       o.harnessTargets ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                       GL_RENDERBUFFER, depth);
        if (o.harnessTargets) {
            glCreateTextures(GL_TEXTURE_2D, 1, &visibility);
            glTextureStorage2D(visibility, 1, GL_RGBA16F, o.width, o.height);
            glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, visibility, 0);
            const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
            glNamedFramebufferDrawBuffers(fbo, 2, buffers);
        }
        if (glCheckNamedFramebufferStatus(mapFbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
            glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("handshadow: framebuffer incomplete", ExitCode::Failure);

        // Constant uniforms once: nothing moves between frames.

        const glm::vec3 lc = light.color * light.intensity;
        glProgramUniformMatrix4fv(depthProgram, 8, 1, GL_FALSE, glm::value_ptr(lightViewProj));
        glProgramUniformMatrix4fv(litProgram, 5, 1, GL_FALSE, glm::value_ptr(viewProj));
        glProgramUniformMatrix4fv(litProgram, 9, 1, GL_FALSE, glm::value_ptr(shadowMatrix));
        const float type = light.type == LightType::Directional ? 0.0f : 2.0f;
        glProgramUniform4f(litProgram, 13, light.position.x, light.position.y, light.position.z, type);
        const glm::vec3 dir = glm::normalize(light.direction);
        glProgramUniform4f(litProgram, 14, dir.x, dir.y, dir.z, std::cos(glm::radians(light.spotOuterDeg)));
        glProgramUniform4f(litProgram, 15, lc.r, lc.g, lc.b, light.range);
        glProgramUniform4f(litProgram, 16, scene.ambient.r, scene.ambient.g, scene.ambient.b,
                           std::cos(glm::radians(light.spotInnerDeg)));
        glEnable(GL_DEPTH_TEST);

        auto drawInstances = [&](bool castersOnly, bool colours) {
            for (const Instance& inst : scene.instances) {
                if (castersOnly && !inst.castsShadow) continue;
                glBindVertexArray(meshes[inst.mesh].vao);
                glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(inst.model));
                if (colours) glUniform3f(4, inst.color.r, inst.color.g, inst.color.b);
                glDrawElements(GL_TRIANGLES, meshes[inst.mesh].count, GL_UNSIGNED_INT, nullptr);
            }
        };
        auto frame = [&](double& submitMs) {
            auto t0 = Clock::now();
            // Depth pass.
            glBindFramebuffer(GL_FRAMEBUFFER, mapFbo);
            glViewport(0, 0, o.mapSize, o.mapSize);
            glClear(GL_DEPTH_BUFFER_BIT);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(2.0f, 2.0f);
            glUseProgram(depthProgram);
            drawInstances(true, false);
            glDisable(GL_POLYGON_OFFSET_FILL);
            // Lit pass.
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glViewport(0, 0, o.width, o.height);
            const GLfloat sky[] = {0.55f, 0.65f, 0.8f, 1.0f}, lit[] = {1.0f, 1.0f, 1.0f, 1.0f};
            glClearBufferfv(GL_COLOR, 0, sky);
            if (o.harnessTargets) glClearBufferfv(GL_COLOR, 1, lit);
            glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
            glUseProgram(litProgram);
            glBindTextureUnit(0, map);
            drawInstances(false, true);
            auto t1 = Clock::now();
            glFinish();
            auto t2 = Clock::now();
            submitMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
            return std::chrono::duration<double, std::milli>(t2 - t0).count();
        };

        double submit = 0.0;
        for (int i = 0; i < o.warmup; ++i) frame(submit);
        std::vector<double> wall, cpu;
        for (int i = 0; i < o.frames; ++i) {
            wall.push_back(frame(submit));
            cpu.push_back(submit);
        }
        if (GLenum err = glGetError(); err != GL_NO_ERROR)
            throw Error("handshadow: GL error 0x" + std::to_string(err), ExitCode::Failure);
        if (!o.png.empty()) writePng(o.png, o.width, o.height);

        std::printf("renderer %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
        std::printf(
            "scene %s, %zu instances, %zu triangles, camera %s, %dx%d, map %d^2, %d frames after %d\n",
            scene.name.c_str(), scene.instances.size(), scene.totalTriangles(), o.camera.c_str(), o.width,
            o.height, o.mapSize, o.frames, o.warmup);
        std::printf("handshadow  wall median %.3f ms  cpu submit median %.3f ms\n", median(wall),
                    median(cpu));
        std::printf("csv,handshadow,%s,%d,%d,%d,%.4f,%.4f,%s\n", scene.name.c_str(), o.width, o.height,
                    o.mapSize, median(wall), median(cpu),
                    o.harnessTargets ? "harness_targets" : "colour_depth");
        return 0;
    } catch (const Error& e) {
        std::cerr << e.what() << "\n";
        return int(e.code());
    } catch (const std::exception& e) {
        std::cerr << "handshadow: " << e.what() << "\n";
        return 1;
    }
}
