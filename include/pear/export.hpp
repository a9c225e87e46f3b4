// pear: which declarations form the shared library's interface. pear is built with hidden
// symbol visibility; PEAR_API marks what a program may link against.
#pragma once

#if defined(_WIN32) || defined(__CYGWIN__)
#define PEAR_API
#elif defined(__GNUC__) || defined(__clang__)
#define PEAR_API __attribute__((visibility("default")))
#else
#define PEAR_API
#endif
