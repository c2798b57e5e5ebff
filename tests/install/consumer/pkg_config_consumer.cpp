// Built with `c++ $(pkg-config --cflags --libs vsl)` against an installed vsl: loads a world and
// builds its localizer. Exit code 0 when the world has objects.
#include <cstdio>

#include "vsl/localization/localizer.hpp"
#include "vsl/world/world_io.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const vsl::world::WorldModel world = vsl::world::load_world(argv[1]);
  const vsl::localization::Localizer localizer(world, {});
  std::printf("%zu objects\n", localizer.world().objects.size());
  return world.objects.empty() ? 1 : 0;
}
