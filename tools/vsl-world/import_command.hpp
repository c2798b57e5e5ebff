// `vsl-world import`: building models (URDF, SDF, meshes, VRML) into one vsl world file.
#pragma once

namespace vsl::world_tool {

// argv[0] is "import". Returns the exit code: 0 done, 2 bad usage or file.
int run_import(int argc, char** argv);

}  // namespace vsl::world_tool
