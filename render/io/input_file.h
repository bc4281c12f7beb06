// The input-file guards under their former name, for the mesh readers that still include it.
// They live in core/input_file.h (textures read files too, and texture/ sits below io/);
// include that instead, and delete this file when nothing includes it.
#pragma once

#include "core/input_file.h"
