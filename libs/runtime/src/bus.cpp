#include "vsl/runtime/bus.hpp"

#include "vsl/runtime/typed.hpp"

namespace vsl::runtime {

void Bus::report_decode_error(const std::string& channel, std::size_t size,
                              const std::type_info& type) {
  ++counters_.decode_errors;
  log_.warn(channel, ": cannot decode ", size, " bytes as ", lcm_type_name(type));
}

}  // namespace vsl::runtime
