# Bounds checks for the C++ decoders that lcm-gen 1.3.1 generates (run with cmake -P).
#
# The stock decoders trust the length fields of a message: a garbled or hostile buffer with a
# negative array count or string length makes std::vector::resize / std::string::assign throw
# std::length_error (which, thrown through LCM's C callback, ends the process), and a huge count
# makes it allocate and zero up to gigabytes before noticing the buffer is short. Also, a
# primitive array whose count is 0 is not resized, so decoding into a reused message keeps the
# previous elements. This script rewrites the generated headers so that decode() returns -1 for
# such buffers and always resizes:
#   - every array count must lie in [0, bytes left] (each element takes at least one byte), checked
#     before the resize;
#   - every string length (which includes the terminating NUL) must lie in [1, bytes left].
# The wire format and the fingerprints are unchanged. If a future lcm-gen generates code of another
# shape, the counts below no longer match and the build stops here instead of silently shipping
# unchecked decoders.
#
# Usage: cmake -DHEADER_DIR=<dir of the generated vsl/*.hpp> -DTYPES=<type>,<type>,... -P harden_cpp.cmake

if(NOT HEADER_DIR OR NOT TYPES)
  message(FATAL_ERROR "harden_cpp.cmake: pass -DHEADER_DIR=<dir> -DTYPES=<comma-separated type names>")
endif()
string(REPLACE "," ";" _types "${TYPES}")
set(HEADERS "")
foreach(_type IN LISTS _types)
  list(APPEND HEADERS "${HEADER_DIR}/${_type}.hpp")
endforeach()

set(_id "[A-Za-z0-9_]+")
set(_guard_tag "/* vsl: bounded */")
foreach(_hpp IN LISTS HEADERS)
  file(READ "${_hpp}" _src)
  if(_src MATCHES "vsl: bounded")
    message(FATAL_ERROR "${_hpp}: already processed; regenerate it with lcm-gen first")
  endif()

  string(REGEX MATCHALL "\\.resize\\(" _resizes "${_src}")
  string(REGEX MATCHALL "\\.assign\\(" _assigns "${_src}")
  list(LENGTH _resizes _n_resize)
  list(LENGTH _assigns _n_assign)

  # Primitive arrays: "if(this->N) {\n this->X.resize(this->N);" -> resize always, then decode.
  string(REGEX REPLACE "if\\(this->(${_id})\\) {\n +this->(${_id})\\.resize\\(this->${_id}\\);"
                       "@VSL_RESIZE@(\\2,\\1)\n    if(this->\\1) {" _src "${_src}")
  # Arrays of strings and structs: "this->X.resize(this->N);".
  string(REGEX REPLACE "this->(${_id})\\.resize\\(this->(${_id})\\);" "@VSL_RESIZE@(\\1,\\2)"
                       _src "${_src}")
  string(REGEX REPLACE "@VSL_RESIZE@\\((${_id}),(${_id})\\)"
                       "if(this->\\2 < 0 || this->\\2 > maxlen - pos) return -1; ${_guard_tag}\n    this->\\1.resize(this->\\2);"
                       _src "${_src}")
  # Strings: "if(__len > maxlen - pos) return -1;" -> also reject lengths < 1.
  string(REGEX REPLACE "if\\((__${_id}) > maxlen - pos\\) return -1;"
                       "if(\\1 < 1 || \\1 > maxlen - pos) return -1; ${_guard_tag}" _src "${_src}")

  # (No ";" in these patterns: MATCHALL returns a ";"-separated list.)
  string(REGEX MATCHALL "< 0 \\|\\| this->${_id} > maxlen - pos\\) return -1"
         _array_guards "${_src}")
  string(REGEX MATCHALL "< 1 \\|\\| __${_id} > maxlen - pos\\) return -1"
         _string_guards "${_src}")
  list(LENGTH _array_guards _n_array_guards)
  list(LENGTH _string_guards _n_string_guards)
  if(NOT _n_array_guards EQUAL _n_resize OR NOT _n_string_guards EQUAL _n_assign)
    message(FATAL_ERROR
      "${_hpp}: lcm-gen output has an unexpected shape (${_n_resize} resize, ${_n_array_guards} "
      "array guards; ${_n_assign} assign, ${_n_string_guards} string guards). "
      "Update lcmtypes/harden_cpp.cmake for this lcm-gen version.")
  endif()
  file(WRITE "${_hpp}" "${_src}")
endforeach()
