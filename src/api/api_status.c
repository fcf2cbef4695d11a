/*
 * api_status.c - the public API's version and status names (refray.h).
 */
#include "api/convert.h"

const char *rf_version(void)
{
    return RF_VERSION_STRING;
}

int rf_version_number(void)
{
    return RF_VERSION_NUMBER;
}

const char *rf_status_string(rf_status status)
{
    return status_string((int)status);
}
