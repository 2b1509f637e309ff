// Named scenes: a built-in default problem with its parameters and the function that runs it.
//
// Scene names are `<method>.<scene>` and, with their parameter names and summary keys, form the public
// interface of softgrain: keep them stable. Each method registers its scenes in one function
// (`register_core_scenes`, `register_sd_scenes`, ...); `lib/scenes.cpp` collects them.
#pragma once

#include "core/advice.hpp"
#include "core/parameters.hpp"
#include "core/resources.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace softgrain {

class RunContext;

struct Scene
{
    std::string name;
    std::string description; // one line
    std::vector<ParameterSpec> parameters;
    std::function<void(const Parameters&, RunContext&)> run;
    // Long runs write checkpoints and can be resumed (RunContext::checkpoints, `run --resume`).
    bool checkpoints = false;
    // The memory the run needs at these parameters, checked before it starts (absent: a scene of fixed,
    // small size).
    std::function<MemoryEstimate(const Parameters&)> memory = nullptr;
    // The work-precision sweep of its methods and resolutions that `softgrain advise` reads (absent: none).
    std::optional<SweepTable> sweep = std::nullopt;
    // The scene writes ParaView frames with `run --vtk` (RunContext::vtk).
    bool vtk = false;
    // Why a scene writes no frames by design (empty: none yet), for the refusal of `run --vtk`.
    std::string no_vtk_reason = {};

    // This scene with its memory estimate: registry.add(Scene{...}.needing(estimate)).
    Scene needing(std::function<MemoryEstimate(const Parameters&)> estimate) &&
    {
        memory = std::move(estimate);
        return std::move(*this);
    }
    // This scene with its stored work-precision sweep: registry.add(Scene{...}.advised_by(table)).
    Scene advised_by(SweepTable table) &&
    {
        sweep = std::move(table);
        return std::move(*this);
    }
    // This scene, writing ParaView frames: registry.add(Scene{...}.with_vtk()).
    Scene with_vtk() &&
    {
        vtk = true;
        return std::move(*this);
    }
    // This scene, refusing `run --vtk` for a reason: registry.add(Scene{...}.without_vtk("a timed scene")).
    Scene without_vtk(std::string reason) &&
    {
        no_vtk_reason = std::move(reason);
        return std::move(*this);
    }
};

class SceneRegistry
{
  public:
    void add(Scene scene);
    const Scene& find(const std::string& name) const; // InputError naming the known scenes if absent
    const std::vector<Scene>& all() const { return scenes_; }

  private:
    std::vector<Scene> scenes_;
};

// Every scene softgrain knows, in the order of `softgrain list`.
SceneRegistry all_scenes();

} // namespace softgrain
