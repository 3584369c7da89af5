// The translation unit that compiles test_pch.hpp into the precompiled header the test
// programs reuse (test/CMakeLists.txt); it defines nothing.
