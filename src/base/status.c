/*
 * status.c - the status family's exit codes and names (status.h).
 */
#include "base/status.h"

int status_exit_code(int s)
{
    switch (s) {
    case STATUS_OK: return 0;
    case STATUS_FAIL: return 1;
    case STATUS_USAGE: return 64;
    case STATUS_DATA: return 65;
    case STATUS_NO_INPUT: return 66;
    case STATUS_IO: return 74;
    case STATUS_CANCELLED: return 130;
    default: return 70;
    }
}

int status_from_exit_code(int code)
{
    for (int s = STATUS_OK; s < STATUS_COUNT; s++)
        if (s != STATUS_NO_MEMORY && status_exit_code(s) == code)
            return s;
    return STATUS_INTERNAL;
}

int status_worse(int a, int b)
{
    return status_exit_code(b) > status_exit_code(a) ? b : a;
}

const char *status_string(int s)
{
    switch (s) {
    case STATUS_OK: return "success";
    case STATUS_USAGE: return "invalid argument";
    case STATUS_DATA: return "invalid data";
    case STATUS_NO_INPUT: return "input not found";
    case STATUS_NO_MEMORY: return "out of memory";
    case STATUS_IO: return "input/output error";
    case STATUS_CANCELLED: return "cancelled";
    case STATUS_INTERNAL: return "internal error";
    case STATUS_FAIL: return "check failed";
    default: return "unknown status";
    }
}
