// Catch2's main, built by us so cross builds get one too.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
