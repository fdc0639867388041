/* fuzz_require.h - FUZZ_REQUIRE(cond, fmt, ...): abort with the target's name
 * (FUZZ_NAME, a string the target defines first), the condition and a message
 * when cond does not hold, so the fuzzer records the input. */
#ifndef CVM_FUZZ_REQUIRE_H
#define CVM_FUZZ_REQUIRE_H

#include <stdio.h>
#include <stdlib.h>

#define FUZZ_REQUIRE(cond, ...)                                        \
    do {                                                               \
        if (!(cond)) {                                                 \
            fprintf(stderr, "%s: %s: ", FUZZ_NAME, #cond);             \
            fprintf(stderr, __VA_ARGS__);                              \
            fprintf(stderr, "\n");                                     \
            abort();                                                   \
        }                                                              \
    } while (0)

#endif
