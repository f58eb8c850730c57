// The translation unit that precompiles the tests' common headers (verification/CMakeLists.txt,
// ibms_test_headers); it defines nothing.
