/*
 * conform_report.h - the reports of `refray conform` (spec/conformance.md,
 * "Reports"): the text table and TAP, streamed a row per scene as it
 * finishes; JSON, JUnit XML and a Markdown table of the whole run.
 */
#ifndef REFRAY_CONFORM_REPORT_H
#define REFRAY_CONFORM_REPORT_H

#include <stdio.h>
#include "verify/conform.h"

typedef struct conform_report {
    const char *kit_dir;
    const char *command;
    const conform_result *results;
    int count;
    double seconds;              /* the whole run */
} conform_report;

/* Scenes that passed. */
int conform_passed(const conform_report *rep);

/* A one-line reason (an over-tolerance reason without its worst pixel),
 * "" for a pass, into buf. */
const char *conform_short_reason(const conform_result *r, char *buf, size_t size);

/* The table: a header, then a row per scene with its reason and the tail
 * of the renderer's standard error below a failure, then the summary. */
void conform_text_header(FILE *fp);
void conform_text_row(FILE *fp, const conform_result *r);
void conform_text_summary(FILE *fp, const conform_report *rep);

/* TAP version 13: the plan, then one test line per scene with a YAML
 * block of the figures for a failure. */
void conform_tap_plan(FILE *fp, int count);
void conform_tap_row(FILE *fp, int number, const conform_result *r);

/* The whole run as one JSON object (returns STATUS_OK, or STATUS_USAGE in
 * a build without JSON), as JUnit XML, as a Markdown table.  Each returns
 * STATUS_OK, or STATUS_IO when fp failed. */
int conform_json_write(FILE *fp, const conform_report *rep);
int conform_junit_write(FILE *fp, const conform_report *rep);
int conform_markdown_write(FILE *fp, const conform_report *rep);

#endif
