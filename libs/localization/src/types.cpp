#include "vsl/localization/types.hpp"

namespace vsl::localization {

const char* to_string(Status status) {
  switch (status) {
    case Status::kLocalized:
      return "localized";
    case Status::kAmbiguous:
      return "ambiguous";
    case Status::kFailed:
      return "failed";
  }
  return "failed";
}

}  // namespace vsl::localization
