/* path.c - file-name helpers shared by the readers and writers. */
#include <string.h>

#include "io_internal.h"

int cvm__path_has_ext(const char *path, const char *ext)
{
    size_t n = strlen(path), k = strlen(ext), i;
    if (n <= k)
        return 0;
    for (i = 0; i < k; i++) {
        char c = path[n - k + i];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != ext[i])
            return 0;
    }
    return 1;
}
