// The translation unit that builds the libraries' shared precompiled header
// (cmake/VslTargets.cmake, vsl_library_pch); it has no code of its own.
