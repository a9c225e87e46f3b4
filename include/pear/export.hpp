// pear: which declarations form the shared library's interface. pear is built with hidden
// symbol visibility; PEAR_API marks what a program may link against.
#pragma once

// pear's headers use concepts, std::span and designated initializers: say so plainly rather
// than with a page of errors from the first concept.
#if defined(_MSVC_LANG) ? _MSVC_LANG < 202002L : __cplusplus < 202002L
#error "pear needs C++20: compile with -std=c++20 (or /std:c++20)"
#endif

#if defined(_WIN32) || defined(__CYGWIN__)
#define PEAR_API
#elif defined(__GNUC__) || defined(__clang__)
#define PEAR_API __attribute__((visibility("default")))
#else
#define PEAR_API
#endif
