#pragma once

/**
 * @file
 * What a restart may change (doc/user-guide.md "Checkpoint and restart").
 *
 * A checkpoint stores every parameter of its run as used
 * (CheckpointPolicy::parameters()). A restart continues the same discrete
 * problem, so it compares them with its own and refuses, naming the entry,
 * any difference outside these entries (a trailing `/`: everything
 * below):
 * - load curves: the entries `Function expression`, `Function constants`
 *   and `Variable names` of any subsection (every function subsection is
 *   a load or control curve of the pseudo time);
 * - stepping and solution control: `Load stepping/`, `Newton/`,
 *   `Linear solver/`, `Stability/`, `Eigen analysis/`;
 * - output and checkpoints: `Output/Directory`, `Output/Quiet`,
 *   `Output/Test output`, `Output/VTU interval`, `Output/Write VTU`,
 *   `Checkpoint/`;
 * - the contact normals: `Contact/Pair <k>/Master normal`,
 *   `Contact/Pair <k>/Smoothed normal from`.
 * Everything else defines the problem: the geometry and mesh, the
 * refinements, the degree, the materials, their laws, variants and
 * constants (Wrinkling smoothing included), the supports, load regions,
 * which subsystems exist, the chambers, cables, contact pairs and ties,
 * form finding, and the monitor and probe points (history.csv's columns).
 * Values compare as text without blanks, and numbers by value (`1e-3`
 * equals `0.001`).
 */

#include <pneuma/core/checkpoint.h>

#include <map>
#include <string>

namespace pneuma
{
  /**
   * Compare the parameters stored in @p checkpoint with @p current (those
   * of this input, CheckpointPolicy::parameters()). Throws an InputError
   * naming the first entry outside the list above whose value differs,
   * that only one of them has, with both values and the restart
   * directory.
   */
  void
  check_restart_parameters(const Checkpoint                         &checkpoint,
                           const std::map<std::string, std::string> &current);
} // namespace pneuma
