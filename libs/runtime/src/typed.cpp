#include "vsl/runtime/typed.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>

namespace vsl::runtime {

std::string lcm_type_name(const std::type_info& type) {
  int status = 0;
  const std::unique_ptr<char, void (*)(void*)> demangled(
      abi::__cxa_demangle(type.name(), nullptr, nullptr, &status), std::free);
  const std::string mangled_or_not = status == 0 && demangled ? demangled.get() : type.name();
  // lcm-gen puts package "vsl" in namespace vsl: "vsl::percepts_t" -> "vsl.percepts_t".
  std::string name;
  name.reserve(mangled_or_not.size());
  for (std::size_t i = 0; i < mangled_or_not.size(); ++i) {
    if (mangled_or_not.compare(i, 2, "::") == 0) {
      name.push_back('.');
      ++i;
    } else {
      name.push_back(mangled_or_not[i]);
    }
  }
  return name;
}

}  // namespace vsl::runtime
