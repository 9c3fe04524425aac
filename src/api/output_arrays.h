// The finished mesh as the library's arrays (deltri::api::Mesh): the same items, numbers, order
// and markers as the .node, .ele, .poly, .edge, .neigh, .v.node and .v.edge files the command line
// writes for the same switches (src/io), so a library caller and a script reading the files see one
// mesh.
#pragma once

#define DELTRI_INTERNAL
#include "deltri/deltri.hpp"

#include "pipeline/pipeline.h"
#include "options/options.h"
#include "pslg/pslg.h"

namespace deltri {

// `poly_input`: the input had segments (p), so segments are output as from a .poly.
api::Mesh output_arrays(const PipelineResult& result, const Options& sw, int first_index, bool poly_input);

}  // namespace deltri
