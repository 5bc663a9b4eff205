// The scene registry: one explicit table of every scene (src/Registry.cpp). No static
// self-registration: inside a static library the linker drops object files nothing references, and
// scenes registered that way silently disappear.

#ifndef SCENES_REGISTRY_H
#define SCENES_REGISTRY_H

#include "scenes/Scene.h"

#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace scenes
{
/// Every scene, grouped by category, in a fixed order.
const std::vector<SceneEntry>& registry();

/// The entry called `name`, or nullptr if there is none.
const SceneEntry* findScene(const std::string& name);

/// Comma-separated list of all scene names, for error messages.
std::string sceneNames();

/// Every scene with its description and parameters (value, unit, meaning), one per line: --list.
void printRegistry(std::ostream& out);

/// Builds the scene `name` into `world` with its defaults, the given values replaced. Throws
/// std::invalid_argument for an unknown scene (the message lists the valid names), an unknown parameter
/// (the message lists the scene's parameters) or an out-of-range value.
std::unique_ptr<SceneContent> createScene(btDiscreteDynamicsWorld& world, const std::string& name,
										  const std::vector<std::pair<std::string, double>>& overrides = {});

}  // namespace scenes

#endif  // SCENES_REGISTRY_H
