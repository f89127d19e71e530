// Catch2 (v2, Debian) entry point for the demcal test suite.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
