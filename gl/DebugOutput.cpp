#include "gl/DebugOutput.h"

#include <epoxy/gl.h>

#include <mutex>

#include "core/Error.h"
#include "core/NameTable.h"

namespace sb {
namespace {

constexpr size_t kMaxWarnings = 256; ///< a driver that warns every draw must not grow memory per frame

struct DebugState {
    std::mutex mutex;
    bool installed = false;
    std::string currentPass;
    bool hasError = false; ///< an error message arrived since the last check()
    std::string errorPass; ///< pass running when the first one arrived
    std::string errorText; ///< the driver's text of the first one
    std::vector<std::string> warnings;
    size_t droppedWarnings = 0;
};

DebugState& state() {
    static DebugState s;
    return s;
}

constexpr Named<GLenum> kErrorNames[] = {
    {GL_INVALID_ENUM, "GL_INVALID_ENUM"},
    {GL_INVALID_VALUE, "GL_INVALID_VALUE"},
    {GL_INVALID_OPERATION, "GL_INVALID_OPERATION"},
    {GL_INVALID_FRAMEBUFFER_OPERATION, "GL_INVALID_FRAMEBUFFER_OPERATION"},
    {GL_OUT_OF_MEMORY, "GL_OUT_OF_MEMORY"},
    {GL_STACK_OVERFLOW, "GL_STACK_OVERFLOW"},
    {GL_STACK_UNDERFLOW, "GL_STACK_UNDERFLOW"},
};
constexpr NameTable kErrors{kErrorNames};

const char* errorName(GLenum code) {
    return kErrors.name(code, "GL error");
}

std::string errorMessage(const std::string& pass, GLenum code, const std::string& driverMessage) {
    std::string text = "GL error in pass '" + pass + "': ";
    std::string name = code == GL_NO_ERROR ? "" : errorName(code);
    if (driverMessage.empty()) return text + name; // glGetError fallback: the enum is all there is
    // Mesa already starts its messages with the enum ("GL_INVALID_ENUM in glTexImage2D(...)").
    if (!name.empty() && driverMessage.rfind(name, 0) != 0) text += name + ": ";
    return text + driverMessage;
}

bool isError(GLenum source, GLenum type, GLenum severity) {
    // Compile/link failures arrive from the shader compiler too; ProgramCache reports them with file and
    // line, and a caught compile error must not fail the next unrelated check().
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return false;
    return type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei length,
                               const GLchar* message, const void*) {
    DebugState& s = state();
    std::lock_guard lock(s.mutex);
    std::string text = length >= 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message);
    if (isError(source, type, severity)) {
        // Only recorded: throwing through the driver's stack is undefined behaviour.
        if (!s.hasError) {
            s.hasError = true;
            s.errorPass = s.currentPass;
            s.errorText = text;
        }
        return;
    }
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    if (s.warnings.size() < kMaxWarnings) {
        s.warnings.push_back(text);
    } else {
        ++s.droppedWarnings;
    }
}

/// Clears the GL error flags (several may be set) and returns the first.
GLenum takeGlError() {
    GLenum first = glGetError();
    for (GLenum next = first; next != GL_NO_ERROR;) next = glGetError();
    return first;
}

} // namespace

bool DebugOutput::install() {
    DebugState& s = state();
    bool available = epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug");
    {
        std::lock_guard lock(s.mutex);
        s.installed = available;
    }
    if (!available) return false;
    // Enabled explicitly: non-debug contexts (OSMesa has no debug flag) start with output disabled.
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    return true;
}

void DebugOutput::setCurrentPass(const std::string& name) {
    std::lock_guard lock(state().mutex);
    state().currentPass = name;
}

const std::string& DebugOutput::currentPass() {
    return state().currentPass;
}

void DebugOutput::check() {
    DebugState& s = state();
    // glGetError is read even with KHR_debug: it clears the flag (else the same error would be reported
    // again) and supplies the enum name for drivers whose messages lack it.
    GLenum code = takeGlError();
    std::string message;
    {
        std::lock_guard lock(s.mutex);
        if (s.hasError) {
            message = errorMessage(s.errorPass, code, s.errorText);
            s.hasError = false;
        } else if (code != GL_NO_ERROR) {
            message = errorMessage(s.currentPass, code, "");
        }
    }
    if (!message.empty()) throw Error(message, ExitCode::Failure);
}

std::vector<std::string> DebugOutput::takeWarnings() {
    DebugState& s = state();
    std::lock_guard lock(s.mutex);
    std::vector<std::string> taken = std::move(s.warnings);
    s.warnings.clear();
    if (s.droppedWarnings > 0) taken.push_back(std::to_string(s.droppedWarnings) + " more warnings not kept");
    s.droppedWarnings = 0;
    return taken;
}

} // namespace sb
