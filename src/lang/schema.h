/*
 * schema.h - which properties each block takes.  Both the parser (for
 * "unknown property ... did you mean" on a syntax error) and the lowering
 * pass (to check and read properties) use this one table.
 */
#ifndef REFRAY_SCHEMA_H
#define REFRAY_SCHEMA_H

#include "lang/keywords.h"

enum { SCHEMA_MAX_PROPS = 12 };

typedef struct block_schema {
    keyword_id block;                       /* KW_SPHERE, ..., KW_MATERIAL */
    int prop_count;
    keyword_id props[SCHEMA_MAX_PROPS];
} block_schema;

/* The schema of a block keyword, or NULL when the word does not open a block. */
const block_schema *schema_of(keyword_id block);

/* Whether block takes property prop. */
int schema_has(const block_schema *schema, keyword_id prop);

/* Writes "a, b, c" (the property names) into buf. */
void schema_list(const block_schema *schema, char *buf, size_t size);

#endif
