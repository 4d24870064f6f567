#include "scenes/ProxyCollection.h"

#include <algorithm>
#include <map>

namespace sb {

glm::mat4 ProxyCollection::sanitizeFrame(const glm::mat4& frame, float minimum) {
    glm::mat4 out = frame;
    glm::vec3 axes[3] = {glm::vec3(frame[0]), glm::vec3(frame[1]), glm::vec3(frame[2])};
    bool ok[3];
    for (int i = 0; i < 3; ++i) ok[i] = glm::length(axes[i]) >= minimum;
    // Directions for the short axes: perpendicular to the good ones, else the unit axes.
    for (int i = 0; i < 3; ++i) {
        if (ok[i]) continue;
        const glm::vec3 &a = axes[(i + 1) % 3], &b = axes[(i + 2) % 3];
        const bool okA = ok[(i + 1) % 3], okB = ok[(i + 2) % 3];
        glm::vec3 dir(0.0f);
        dir[i] = 1.0f;
        if (okA && okB) {
            dir = glm::cross(a, b);
        } else if (okA || okB) {
            const glm::vec3 good = okA ? a : b;
            glm::vec3 candidate = glm::cross(good, dir);
            if (glm::length(candidate) < 1e-6f * glm::length(good)) {
                glm::vec3 other(0.0f);
                other[(i + 1) % 3] = 1.0f;
                candidate = glm::cross(good, other);
            }
            dir = glm::cross(candidate, good); // in the plane of good and dir, perpendicular to good
        }
        axes[i] = glm::normalize(dir) * minimum;
        ok[i] = true;
        out[i] = glm::vec4(axes[i], 0.0f);
    }
    return out;
}

std::vector<ShadowProxy> ProxyCollection::collect(const Scene& scene, bool fitAll,
                                                  std::vector<uint32_t>* owners) {
    const Aabb bounds = scene.computeBounds(false);
    const float minimum = 1e-6f * std::max(1.0f, bounds.empty() ? 1.0f : glm::length(bounds.extent()));
    std::map<uint32_t, ShadowProxy> fitted; // per mesh, object space: fit(mesh, M) = M * fit(mesh, I)
    std::vector<ShadowProxy> out;
    if (owners) owners->clear();
    for (const Instance& inst : scene.instances) {
        if (!inst.castsShadow) continue;
        const Mesh& mesh = scene.meshes[inst.mesh];
        std::vector<ShadowProxy> local;
        if (mesh.proxiesDeclared && !fitAll) {
            local = mesh.proxies;
        } else if (!mesh.positions.empty()) {
            auto it = fitted.find(inst.mesh);
            if (it == fitted.end())
                it = fitted.emplace(inst.mesh, ShadowProxy::fit(mesh, glm::mat4(1.0f))).first;
            local.push_back(it->second);
        }
        for (ShadowProxy p : local) {
            p.frame = sanitizeFrame(inst.model * p.frame, minimum);
            if (p.diffuseFromInstance) p.diffuse = inst.color;
            out.push_back(p);
            if (owners) owners->push_back(inst.objectId);
        }
    }
    return out;
}

} // namespace sb
