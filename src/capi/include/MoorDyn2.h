/* librodyn: MoorDyn v2's C API (its source/MoorDyn2.h, Line.h, Point.h), served by rodyn:
 * a system read from a MoorDyn v2 input file, its statics solved by MoorDyn_Init and
 * its dynamics advanced by MoorDyn_Step with rodyn's implicit steps. docs/capi.md lists
 * the functions implemented; the others are not declared here. */
#ifndef __MOORDYN2_H__
#define __MOORDYN2_H__

#include "MoorDynAPI.h"
#include <stdlib.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C"
{
#endif

/** A mooring system, a line and a point of it */
typedef struct __MoorDyn* MoorDyn;
typedef struct __MoorDynLine* MoorDynLine;
typedef struct __MoorDynPoint* MoorDynPoint;
typedef struct __MoorDynBody* MoorDynBody;

MoorDyn DECLDIR MoorDyn_Create(const char* infilename);
int DECLDIR MoorDyn_NCoupledDOF(MoorDyn system, unsigned int* n);
int DECLDIR MoorDyn_SetVerbosity(MoorDyn system, int verbosity);
int DECLDIR MoorDyn_SetLogLevel(MoorDyn system, int verbosity);
int DECLDIR MoorDyn_Init(MoorDyn system, const double* x, const double* xd);
int DECLDIR MoorDyn_Step(MoorDyn system, const double* x, const double* xd, double* f,
                         double* t, double* dt);
int DECLDIR MoorDyn_Close(MoorDyn system);

int DECLDIR MoorDyn_GetNumberPoints(MoorDyn system, unsigned int* n);
MoorDynPoint DECLDIR MoorDyn_GetPoint(MoorDyn system, unsigned int c);
int DECLDIR MoorDyn_GetNumberLines(MoorDyn system, unsigned int* n);
MoorDynLine DECLDIR MoorDyn_GetLine(MoorDyn system, unsigned int l);
int DECLDIR MoorDyn_GetNumberBodies(MoorDyn system, unsigned int* n);
MoorDynBody DECLDIR MoorDyn_GetBody(MoorDyn system, unsigned int b);
int DECLDIR MoorDyn_GetFASTtens(MoorDyn system, const int* numLines, float FairHTen[],
                                float FairVTen[], float AnchHTen[], float AnchVTen[]);
int DECLDIR MoorDyn_BreakLine(MoorDyn system, MoorDynPoint point, MoorDynLine line);

int DECLDIR MoorDyn_GetLineID(MoorDynLine l, int* id);
int DECLDIR MoorDyn_GetLineN(MoorDynLine l, unsigned int* n);
int DECLDIR MoorDyn_GetLineNumberNodes(MoorDynLine l, unsigned int* n);
int DECLDIR MoorDyn_GetLineUnstretchedLength(MoorDynLine l, double* ul);
int DECLDIR MoorDyn_GetLineNodePos(MoorDynLine l, unsigned int i, double pos[3]);
int DECLDIR MoorDyn_GetLineNodeVel(MoorDynLine l, unsigned int i, double vel[3]);
int DECLDIR MoorDyn_GetLineNodeTen(MoorDynLine l, unsigned int i, double t[3]);
int DECLDIR MoorDyn_GetLineNodeCurv(MoorDynLine l, unsigned int i, double* c);
int DECLDIR MoorDyn_GetLineFairTen(MoorDynLine l, double* t);
int DECLDIR MoorDyn_GetLineMaxTen(MoorDynLine l, double* t);

int DECLDIR MoorDyn_GetPointID(MoorDynPoint point, int* id);
int DECLDIR MoorDyn_GetPointType(MoorDynPoint point, int* t);
int DECLDIR MoorDyn_GetPointPos(MoorDynPoint point, double pos[3]);
int DECLDIR MoorDyn_GetPointForce(MoorDynPoint point, double f[3]);

int DECLDIR MoorDyn_GetBodyID(MoorDynBody body, int* id);
int DECLDIR MoorDyn_GetBodyState(MoorDynBody body, double r[6], double rd[6]);

#ifdef __cplusplus
}
#endif

#endif
