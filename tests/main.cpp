// SPDX-License-Identifier: GPL-2.0-or-later
/** @file main.cpp
 *  The Catch2 test runner. */
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
