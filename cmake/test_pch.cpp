// The translation unit that builds the test executables' shared precompiled header
// (vsl_test_pch, VslTargets.cmake); it has no code of its own.
