#include "core/scene.hpp"

#include "core/errors.hpp"

#include <stdexcept>

namespace softgrain {

void SceneRegistry::add(Scene scene)
{
    for (const auto& known : scenes_)
        if (known.name == scene.name) throw std::logic_error("scene '" + scene.name + "' registered twice");
    scenes_.push_back(std::move(scene));
}

const Scene& SceneRegistry::find(const std::string& name) const
{
    for (const auto& scene : scenes_)
        if (scene.name == name) return scene;
    std::string names;
    for (const auto& scene : scenes_)
        names += (names.empty() ? "" : ", ") + scene.name;
    throw InputError("unknown scene '" + name + "'; known scenes: " + names + " (or a .toml scene file)");
}

} // namespace softgrain
