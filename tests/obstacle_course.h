#pragma once

// The shell obstacle course's tests (tests/shell_roof, shell_hemisphere,
// shell_pinched_cylinder) run parameter_files/<name>.prm on
// meshes/<name>.msh.

#include "test_tools.h"

#include <string>

namespace pneuma_test
{
  /// The quiet settings of the course's @p name on its mesh refined
  /// @p refinements times, with @p extra on top.
  inline Settings
  course_settings(const std::string &name,
                  const unsigned int refinements,
                  const Settings    &extra = {})
  {
    Settings settings = quiet();
    settings.insert(
      settings.end(),
      {{"Geometry/Global refinements", std::to_string(refinements)},
       {"Geometry/gmsh/Mesh file",
        std::string(PNEUMA_SOURCE_DIR) + "/meshes/" + name + ".msh"}});
    settings.insert(settings.end(), extra.begin(), extra.end());
    return settings;
  }

  /// The simulator of parameter_files/@p name.prm with course_settings.
  inline std::unique_ptr<pneuma::Simulator>
  make_course(const std::string &name,
              const unsigned int refinements,
              const Settings    &extra = {})
  {
    return make(course_settings(name, refinements, extra),
                std::string(PNEUMA_SOURCE_DIR) + "/parameter_files/" + name
                  + ".prm");
  }

  /// Run parameter_files/@p name.prm quietly on meshes/@p name.msh refined
  /// @p refinements times, with @p extra on top.
  inline pneuma::RunResult
  run_course(const std::string &name,
             const unsigned int refinements,
             const Settings    &extra = {})
  {
    return make_course(name, refinements, extra)->run();
  }
} // namespace pneuma_test
