/* input_names.c - names input items in messages in the terms of the file they were read from. */
#include <stdio.h>
#include <string.h>

#include "api_internal.h"

const char *cvm__src_where(char *buf, size_t cap, const cvm__item_src *src, size_t k)
{
    int64_t num, line;
    if (cvm__item_src_get(src, k, &num, &line))
        snprintf(buf, cap, "%s:%lld: ", src->file, (long long)line);
    else if (cap)
        buf[0] = '\0';
    return buf;
}

long long cvm__src_num(const cvm__item_src *src, size_t k)
{
    int64_t num, line;
    cvm__item_src_get(src, k, &num, &line);
    return (long long)num;
}

const char *cvm__src_also(char *buf, size_t cap, const cvm__item_src *src, size_t k,
                          const cvm__item_src *primary)
{
    int64_t num, line;
    if (!cvm__item_src_get(src, k, &num, &line)) {
        if (cap)
            buf[0] = '\0';
    } else if (primary && primary->file && strcmp(primary->file, src->file) == 0) {
        snprintf(buf, cap, " (line %lld)", (long long)line);
    } else {
        snprintf(buf, cap, " (%s:%lld)", src->file, (long long)line);
    }
    return buf;
}
