#include "mapped_keywords.hpp"

#include "keywords.hpp"

namespace py_rl {

normal_mapping::MappedView mapped_view(py::handle models, const std::optional<Camera>& camera,
                                       const std::vector<double>& light,
                                       const std::string& normal_map, const std::string& tangents,
                                       const std::string& specular, const std::string& filter,
                                       bool naive, bool one_light) {
    normal_mapping::MappedView request;
    request.view = view_options(models, camera, light);
    request.options.normal_map = choice("--normal-map", normal_map, normal_mapping::kNormalMaps);
    request.tangents = choice("--tangents", tangents, normal_mapping::kTangentMethods);
    request.options.specular = choice("--specular", specular, shading::kSpeculars);
    request.options.filter = choice("--filter", filter, textures::kFilters);
    request.naive = naive;
    request.one_light = one_light;
    return request;
}

}  // namespace py_rl
