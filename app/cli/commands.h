// The raystudio-cli sub-commands; each returns the process exit code (0, 1 or 2).
#pragma once

#include "accel/ray_engine.h"
#include "io/scene_io.h"

namespace rs::cli {

class Arguments;

int runRender(int argc, char** argv);
int runValidate(int argc, char** argv);
int runBench(int argc, char** argv);
int runDrag(int argc, char** argv);
int runMerge(int argc, char** argv);
int runFarm(int argc, char** argv);
int runImport(int argc, char** argv);

/// Loads a scene for a command; prints every error to stderr and returns false on failure.
/// Warnings (images that cannot be read) are printed too; `warned` says whether there were.
bool loadSceneOrReport(const std::string& path, SceneDocument& doc, bool* warned = nullptr);

/// Applies the shared render-setting overrides (--width, --height, --max-depth, --min-weight,
/// --shadow-samples, --supersampling); throws UsageError on bad values.
void applyRenderOverrides(const Arguments& args, RenderSettings& settings);

/// The ray engine `--engine embree|builtin` names (Embree when absent); UsageError otherwise.
EngineKind engineOption(const Arguments& args);

}  // namespace rs::cli
