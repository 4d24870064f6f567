#include "shading/ShaderSources.h"

#include <algorithm>

namespace sb {

std::vector<std::pair<ShaderStage, const std::string*>> ShaderSources::stages() const {
    if (!compute.empty()) return {{ShaderStage::Compute, &compute}};
    std::vector<std::pair<ShaderStage, const std::string*>> out;
    if (!mesh.empty())
        out.emplace_back(ShaderStage::Mesh, &mesh);
    else
        out.emplace_back(ShaderStage::Vertex, &vertex);
    if (!geometry.empty()) out.emplace_back(ShaderStage::Geometry, &geometry);
    if (!fragment.empty()) out.emplace_back(ShaderStage::Fragment, &fragment);
    return out;
}

std::string ShaderSources::programName() const {
    std::string name;
    for (const auto& [stage, file] : stages()) {
        std::string part = *file;
        std::replace(part.begin(), part.end(), '/', '-');
        name += (name.empty() ? "" : "+") + part;
    }
    return name;
}

std::string ShaderSources::describe() const {
    if (!compute.empty()) return "compute '" + compute + "'";
    std::string text = mesh.empty() ? "vertex '" + vertex + "'" : "mesh '" + mesh + "'";
    if (!fragment.empty()) text += ", fragment '" + fragment + "'";
    if (!geometry.empty()) text += ", geometry '" + geometry + "'";
    return text;
}

} // namespace sb
