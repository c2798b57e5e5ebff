// vsl-fusion: PERCEPTS -> FUSED_PERCEPTS (paper §2.1.1). Accumulates the percepts of the current
// localization request's scan; each time the localizer's status for it enters FUSING, fuses them
// (isolated percepts rejected, per-type mean shift, T_s, Eq. 4) and publishes the fused set.
// Config: config/fusion.yaml; behaviour: docs/fusion.md; messages: docs/messages.md.
#include "vsl/runtime/main.hpp"
#include "fusion_daemon.hpp"
#include "fusion_setup.hpp"
#include "vsl/config/node.hpp"

int main(int argc, char** argv) {
  const vsl::runtime::ProgramInfo program{
      "vsl-fusion",
      "Fuses the percepts of a scan (paper 2.1.1): PERCEPTS of the current request (started by\n"
      "LOCALIZE_REQUEST) are accumulated; each time LOCALIZER_STATUS for that request enters\n"
      "FUSING, isolated percepts are rejected (varpi), each type is clustered by mean shift,\n"
      "modes that pass the confidence criterion C / T_s > E_min (Eq. 4, relaxed by iota) are\n"
      "published on FUSED_PERCEPTS with the request_id. After a restart, a status for an\n"
      "unknown request adopts it. Config: config/fusion.yaml (head, fusion:).",
      true};
  return vsl::runtime::daemon_main(
      argc, argv, program, [](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
        vsl::fusion_daemon::FusionDaemon fusion(daemon, vsl::fusion_daemon::load_fusion(config));
        return daemon.run();
      });
}
