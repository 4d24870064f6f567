#include "techniques/shadowmap/DepthLayers.h"

#include <string>

#include "core/Error.h"

namespace sb {

namespace {
void checkComplete(GLuint fbo, const std::string& owner) {
    const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error(owner + ": depth framebuffer incomplete (status 0x" + std::to_string(status) + ")",
                    ExitCode::Failure);
}

GLuint depthOnlyFramebuffer() {
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    glNamedFramebufferReadBuffer(fbo, GL_NONE);
    return fbo;
}
} // namespace

void DepthLayers::release() {
    if (!mFbos.empty()) glDeleteFramebuffers(GLsizei(mFbos.size()), mFbos.data());
    mFbos.clear();
    if (mLayeredFbo) glDeleteFramebuffers(1, &mLayeredFbo);
    mLayeredFbo = 0;
    if (mTexture) glDeleteTextures(1, &mTexture);
    mTexture = 0;
    mSize = mLayers = 0;
    mTarget = 0;
    mLayered = false;
}

void DepthLayers::allocate(GLenum target, int size, int layers, bool layered) {
    if (target == mTarget && size == mSize && layers == mLayers && layered == mLayered) return;
    release();
    if (layers <= 0) return;
    glCreateTextures(target, 1, &mTexture);
    glTextureStorage3D(mTexture, 1, GL_DEPTH_COMPONENT24, size, size, layers);
    glTextureParameteri(mTexture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mTexture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mTexture, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    // Hardware compare with LINEAR: the four comparison results are filtered (bilinear PCF).
    glTextureParameteri(mTexture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(mTexture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(mTexture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(mTexture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    mFbos.resize(size_t(layers));
    for (int i = 0; i < layers; ++i) {
        mFbos[size_t(i)] = depthOnlyFramebuffer();
        glNamedFramebufferTextureLayer(mFbos[size_t(i)], GL_DEPTH_ATTACHMENT, mTexture, 0, i);
        checkComplete(mFbos[size_t(i)], mOwner);
    }
    if (layered) {
        mLayeredFbo = depthOnlyFramebuffer();
        glNamedFramebufferTexture(mLayeredFbo, GL_DEPTH_ATTACHMENT, mTexture, 0);
        checkComplete(mLayeredFbo, mOwner);
    }
    mTarget = target;
    mSize = size;
    mLayers = layers;
    mLayered = layered;
}

void DepthLayers::beginLayer(int layer) const {
    glBindFramebuffer(GL_FRAMEBUFFER, mFbos[size_t(layer)]);
    glClear(GL_DEPTH_BUFFER_BIT);
}

void DepthLayers::beginLayered() const {
    glBindFramebuffer(GL_FRAMEBUFFER, mLayeredFbo);
    glClear(GL_DEPTH_BUFFER_BIT);
}

} // namespace sb
