/*
 * diag_print.h - diagnostics printed as compilers print them:
 *
 *   scene.scene:3:17: error: radius must be > 0, got -1
 *       3 | sphere { radius -1 }
 *         |                 ^~
 *
 * and "refray: error: MESSAGE" for a message without location.
 */
#ifndef REFRAY_DIAG_PRINT_H
#define REFRAY_DIAG_PRINT_H

#include <stdio.h>
#include "base/diag.h"

/* A diag_sink: prints r to the FILE * in stream. */
void diag_print(void *stream, const diag_record *r);

#endif
