// vsl_consumer [WORLD] [LOCALIZER_CONFIG]: what a robot project does with an installed vsl.
// Perceives the installed kitchen's doors and handles from a known pose (exact ego positions),
// localizes with vsl::localization, prints the pose; encodes and decodes one LCM message.
// Exit code 0 when the pose is found within 1 cm and the message round-trips.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/world/world_io.hpp"

int main(int argc, char** argv) {
  try {
    const std::string world_path =
        argc > 1 ? argv[1] : std::string(VSL_DATA_DIR) + "/config/worlds/kitchen.yaml";
    const vsl::world::WorldModel world = vsl::world::load_world(world_path);
    vsl::localization::LocalizerOptions options;
    if (argc > 2) {
      options = vsl::localization::localizer_options_from(vsl::config::Node::load_file(argv[2]));
    }
    const vsl::localization::Localizer localizer(world, options);

    // The robot at (4.4, 1.0) m facing 135 deg; it sees the fronts and handles within 3.5 m.
    Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
    world_T_ego.translate(Eigen::Vector3d(4.4, 1.0, 0.0));
    world_T_ego.rotate(Eigen::AngleAxisd(135.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()));
    std::vector<vsl::localization::FusedPercept> percepts;
    for (const auto& object : world.objects) {
      if (object.type != "door" && object.type != "handle") continue;
      const Eigen::Vector3d ego = world_T_ego.inverse() * object.world_position_m;
      if (ego.x() < 0.3 || ego.norm() > 3.5) continue;
      percepts.push_back({object.type, ego, std::nullopt, 4});
    }
    const vsl::localization::LocalizationResult result = localizer.localize(percepts);
    const Eigen::Vector3d t = result.world_T_ego.translation();
    const double error_m = (t - world_T_ego.translation()).norm();
    std::printf("%zu percepts; status %d; pose (%.4f, %.4f, %.4f) m; error %.4f m\n",
                percepts.size(), static_cast<int>(result.status), t.x(), t.y(), t.z(), error_m);

    vsl::pose_estimate_t message{};
    message.request_id = 42;
    std::vector<std::uint8_t> buffer(static_cast<std::size_t>(message.getEncodedSize()));
    message.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
    vsl::pose_estimate_t decoded{};
    const bool round_trip = decoded.decode(buffer.data(), 0, static_cast<int>(buffer.size())) > 0 &&
                            decoded.request_id == 42;
    std::printf("pose_estimate_t round trip: %s\n", round_trip ? "ok" : "FAILED");
    return result.status == vsl::localization::Status::kLocalized && error_m < 0.01 && round_trip
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vsl_consumer: %s\n", e.what());
    return 1;
  }
}
