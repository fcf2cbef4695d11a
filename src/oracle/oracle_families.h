/*
 * oracle_families.h - the declarations of every family in the generated
 * oracle_list.h (one ORACLE_FAMILY(name) per family file under src/oracle).
 */
#ifndef REFRAY_ORACLE_FAMILIES_H
#define REFRAY_ORACLE_FAMILIES_H

#include "oracle/oracle.h"

#define ORACLE_FAMILY(name) extern const oracle_family oracle_##name;
#include "oracle_list.h"
#undef ORACLE_FAMILY

#endif
