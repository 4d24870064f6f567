#include "techniques/occluder/OccluderTextures.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "core/Error.h"
#include "core/PngFile.h"
#include "gl/GlStateGuard.h"
#include "gl/TextureFramebuffer.h"

namespace sb {
namespace {

const ShaderSources kBakeSources{"occluder/bake.vert", "occluder/bake.frag", ""};

std::string planeLabel(const ShadowPlane& plane) {
    return "shadow plane '" + plane.name + "'";
}

/// Positions and indices of a mesh on the GPU for the bake (attribute 0 only).
class BakeGeometry {
public:
    explicit BakeGeometry(const Mesh& mesh) {
        glCreateVertexArrays(1, &mVao);
        glCreateBuffers(1, &mVbo);
        glCreateBuffers(1, &mIbo);
        // Storage of at least one element: a zero-size buffer store is an error.
        const glm::vec3 none(0.0f);
        const uint32_t noIndex = 0;
        glNamedBufferStorage(mVbo, GLsizeiptr(std::max<size_t>(1, mesh.positions.size()) * sizeof(glm::vec3)),
                             mesh.positions.empty() ? &none : mesh.positions.data(), 0);
        glNamedBufferStorage(mIbo, GLsizeiptr(std::max<size_t>(1, mesh.indices.size()) * sizeof(uint32_t)),
                             mesh.indices.empty() ? &noIndex : mesh.indices.data(), 0);
        glVertexArrayVertexBuffer(mVao, 0, mVbo, 0, GLsizei(sizeof(glm::vec3)));
        glVertexArrayElementBuffer(mVao, mIbo);
        glEnableVertexArrayAttrib(mVao, 0);
        glVertexArrayAttribFormat(mVao, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(mVao, 0, 0);
    }
    ~BakeGeometry() {
        glDeleteVertexArrays(1, &mVao);
        glDeleteBuffers(1, &mVbo);
        glDeleteBuffers(1, &mIbo);
    }
    BakeGeometry(const BakeGeometry&) = delete;
    BakeGeometry& operator=(const BakeGeometry&) = delete;
    GLuint vao() const { return mVao; }

    static void draw(uint32_t firstIndex, uint32_t count) {
        if (count == 0) return;
        glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(uintptr_t(firstIndex) * sizeof(uint32_t)));
    }

private:
    GLuint mVao = 0, mVbo = 0, mIbo = 0;
};

/// A new R8 texture holding `texels` (row 0 = v near 0), filtered as the technique samples it: LINEAR
/// (the thesis's bilinear magnification softens the jaggies), clamped to the border texels.
GLuint createOccluderTexture(const std::vector<uint8_t>& texels, int width, int height) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_R8, width, height);
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GLint unpackAlignment = 4, unpackBuffer = 0;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glTextureSubImage2D(texture, 0, 0, 0, width, height, GL_RED, GL_UNSIGNED_BYTE, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpackBuffer));
    return texture;
}

} // namespace

void OccluderTextures::requestPrograms(ProgramCache& programs) {
    for (const Defines& d : {Defines{}, Defines{{"BAKE_CLIP", ""}}, Defines{{"BAKE_FULLSCREEN", ""}}})
        programs.get(kBakeSources, d);
}

GLuint OccluderTextures::bake(ProgramCache& programs, const Mesh& mesh, const ShadowPlane& plane,
                              const OccluderBakeOptions& options) {
    OccluderTexels::validate(mesh, plane, options);
    const std::vector<MeshPart> parts = OccluderTexels::parts(mesh, plane);
    // Programs first: a compile error throws before any GL state is touched.
    const Program& draw = programs.get(kBakeSources, {});
    const Program& clipped = programs.get(kBakeSources, {{"BAKE_CLIP", ""}});
    const Program& fill = programs.get(kBakeSources, {{"BAKE_FULLSCREEN", ""}});

    GlStateGuard guard; // everything below, restored also when an exception leaves bake()
    const int n = options.resolution;
    TextureFramebuffer target(planeLabel(plane) + " occluder bake", n, n, {GL_R8});
    BakeGeometry geometry(mesh);
    target.bind();
    for (GLenum e :
         {GL_DEPTH_TEST, GL_CULL_FACE, GL_STENCIL_TEST, GL_BLEND, GL_SCISSOR_TEST, GL_CLIP_DISTANCE0})
        glDisable(e);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLint zero = 0;
    glClearNamedFramebufferfv(target.fbo(), GL_COLOR, 0, white);
    glClearNamedFramebufferiv(target.fbo(), GL_STENCIL, 0, &zero);

    const glm::vec3 right = plane.right / plane.width, up = plane.up / plane.height;
    for (const Program* program : {&draw, &clipped}) {
        glProgramUniform3fv(program->id(), 0, 1, &plane.origin.x);
        glProgramUniform3fv(program->id(), 1, 1, &right.x);
        glProgramUniform3fv(program->id(), 2, 1, &up.x);
    }
    glProgramUniform3fv(clipped.id(), 3, 1, &plane.normal.x); // only BAKE_CLIP reads the normal
    draw.use();
    glBindVertexArray(geometry.vao());

    // The silhouette: the parts' triangles, both facings, black on white.
    if (options.silhouette)
        for (const MeshPart& part : parts) BakeGeometry::draw(part.firstIndex, part.indexCount);

    if (options.crossSection) {
        // The cross-section (thesis section 5, the fin extended down into the body), marked where the
        // plane point lies inside the solid of the whole mesh. Every triangle on the normal's side of
        // the plane is counted in the stencil, +1 for one facing and -1 for the other: the sum is the
        // winding number of the plane point along the ray that leaves it along +normal, non-zero exactly
        // inside a closed, consistently wound surface. The non-zero rule rather than parity (GL_INVERT)
        // because meshes are unions of overlapping closed parts (the aircraft's fins and stabilisers
        // reach into the fuselage): inside two of them the parity is even, the winding number 2.
        // Safe: a receiver p0 is shadowed by the plane point q only when q lies between p0 and the
        // light (s_I > 0), and then the segment p0 -> light passes through q inside the solid, so the
        // mesh itself occludes that ray (or p0 faces away from the light, the ray entering the solid
        // at p0): marking q can add no shadow the geometry does not cast.
        clipped.use();
        glEnable(GL_CLIP_DISTANCE0);
        glEnable(GL_STENCIL_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        BakeGeometry::draw(0, uint32_t(mesh.indices.size()));
        glDisable(GL_CLIP_DISTANCE0);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        fill.use();
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    std::vector<uint8_t> texels(size_t(n) * size_t(n));
    target.read(GL_COLOR_ATTACHMENT0, GL_RED, GL_UNSIGNED_BYTE, texels.data());
    if (options.dilate > 0) texels = dilate(texels, n, n, options.dilate);
    return createOccluderTexture(texels, n, n);
}

GLuint OccluderTextures::load(const std::string& path) {
    int w = 0, h = 0;
    const std::vector<uint8_t> texels = OccluderTexels::load(path, w, h);
    return createOccluderTexture(texels, w, h);
}

std::vector<uint8_t> OccluderTextures::readBack(GLuint texture, int& width, int& height) {
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
    std::vector<uint8_t> texels(size_t(std::max(width, 0)) * size_t(std::max(height, 0)));
    GLint packAlignment = 4, packBuffer = 0;
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glGetTextureImage(texture, 0, GL_RED, GL_UNSIGNED_BYTE, GLsizei(texels.size()), texels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer));
    return texels;
}

} // namespace sb
