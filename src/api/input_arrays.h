// The library's input arrays (deltri::api::Input) checked and turned into the pipeline's Pslg
// and, for r, the previous mesh: the library's counterpart of the .node/.poly/.ele/.area readers,
// with the same rules and messages, the file:line replaced by the item ("segment 3: ...").
#pragma once

#define DELTRI_INTERNAL
#include "deltri/deltri.hpp"

#include "pipeline/pipeline.h"
#include "pslg/pslg.h"

namespace deltri {

// Numbering: first_index is 0 (z) or 1. With `poly`, segments, holes and regions are read.
// Throws api::Error(DELTRI_INPUT_ERROR, message) for malformed input.
Pslg pslg_from_input(const api::Input& in, int first_index, bool poly);

// r: the triangles (corners numbered from first_index), their attributes and, with `area_bounds`,
// their area bounds (none when the input gives none).
PreviousMesh previous_from_input(const api::Input& in, int first_index, bool area_bounds);

}  // namespace deltri
