/* librodyn: MoorDyn v2's C API (its source/MoorDyn2.h, Line.h, Point.h, Rod.h, Body.h,
 * Waves.h, Seafloor.h), served by rodyn: a system read from a MoorDyn v2 input file, its
 * statics solved by MoorDyn_Init and its dynamics advanced by MoorDyn_Step with rodyn's
 * implicit steps. Every function of MoorDyn v2.7's C API is declared, so that a host
 * written for MoorDyn compiles and links unchanged; docs/capi.md says what each does
 * here. Those not yet served write so on stderr and return MOORDYN_UNHANDLED_ERROR (or a
 * NULL handle). */
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
typedef struct __MoorDynRod* MoorDynRod;
typedef struct __MoorDynWaves* MoorDynWaves;
typedef struct __MoorDynSeafloor* MoorDynSeafloor;

MoorDyn DECLDIR MoorDyn_Create(const char* infilename);
int DECLDIR MoorDyn_NCoupledDOF(MoorDyn system, unsigned int* n);
int DECLDIR MoorDyn_SetVerbosity(MoorDyn system, int verbosity);
int DECLDIR MoorDyn_SetLogLevel(MoorDyn system, int verbosity);
int DECLDIR MoorDyn_Init(MoorDyn system, const double* x, const double* xd);
int DECLDIR MoorDyn_Step(MoorDyn system, const double* x, const double* xd, double* f,
                         double* t, double* dt);
int DECLDIR MoorDyn_Init_NoIC(MoorDyn system, const double* x, const double* xd);
int DECLDIR MoorDyn_Close(MoorDyn system);
int DECLDIR MoorDyn_SetLogFile(MoorDyn system, const char* log_path);
int DECLDIR MoorDyn_Log(MoorDyn system, int level, const char* msg);
MoorDynWaves DECLDIR MoorDyn_GetWaves(MoorDyn system);
MoorDynSeafloor DECLDIR MoorDyn_GetSeafloor(MoorDyn system);
int DECLDIR MoorDyn_ExternalWaveKinInit(MoorDyn system, unsigned int* n);
int DECLDIR MoorDyn_ExternalWaveKinGetN(MoorDyn system, unsigned int* n);
int DECLDIR MoorDyn_ExternalWaveKinGetCoordinates(MoorDyn system, double* r);
int DECLDIR MoorDyn_ExternalWaveKinSet(MoorDyn system, const double* U, const double* Ud,
                                       double t);
int DECLDIR MoorDyn_GetNumberRods(MoorDyn system, unsigned int* n);
MoorDynRod DECLDIR MoorDyn_GetRod(MoorDyn system, unsigned int r);
int DECLDIR MoorDyn_GetDt(MoorDyn system, double* dt);
int DECLDIR MoorDyn_SetDt(MoorDyn system, double dt);
int DECLDIR MoorDyn_GetCFL(MoorDyn system, double* cfl);
int DECLDIR MoorDyn_SetCFL(MoorDyn system, double cfl);
int DECLDIR MoorDyn_GetTimeScheme(MoorDyn system, char* name, size_t* name_len);
int DECLDIR MoorDyn_SetTimeScheme(MoorDyn system, const char* name);
int DECLDIR MoorDyn_SaveState(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_LoadState(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_Serialize(MoorDyn system, size_t* size, uint64_t* data);
int DECLDIR MoorDyn_Deserialize(MoorDyn system, const uint64_t* data);
int DECLDIR MoorDyn_Save(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_Load(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_SaveVTK(MoorDyn system, const char* filename);

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
int DECLDIR MoorDyn_SetLineUnstretchedLength(MoorDynLine l, double ul);
int DECLDIR MoorDyn_SetLineUnstretchedLengthVel(MoorDynLine l, double v);
int DECLDIR MoorDyn_IsLineConstantEA(MoorDynLine l, int* b);
int DECLDIR MoorDyn_GetLineConstantEA(MoorDynLine l, double* EA);
int DECLDIR MoorDyn_SetLineConstantEA(MoorDynLine l, double EA);
int DECLDIR MoorDyn_IsLinePressBend(MoorDynLine l, int* b);
int DECLDIR MoorDyn_SetLinePressBend(MoorDynLine l, int b);
int DECLDIR MoorDyn_SetLinePressInt(MoorDynLine l, const double* p);
int DECLDIR MoorDyn_GetLineNodeForce(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeBendStiff(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeWeight(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeDrag(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeFroudeKrilov(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeSeabedForce(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeM(MoorDynLine l, unsigned int i, double m[3][3]);
int DECLDIR MoorDyn_SaveLineVTK(MoorDynLine l, const char* filename);

int DECLDIR MoorDyn_GetPointID(MoorDynPoint point, int* id);
int DECLDIR MoorDyn_GetPointType(MoorDynPoint point, int* t);
int DECLDIR MoorDyn_GetPointPos(MoorDynPoint point, double pos[3]);
int DECLDIR MoorDyn_GetPointForce(MoorDynPoint point, double f[3]);
int DECLDIR MoorDyn_GetPointVel(MoorDynPoint point, double v[3]);
int DECLDIR MoorDyn_GetPointM(MoorDynPoint point, double m[3][3]);
int DECLDIR MoorDyn_GetPointNAttached(MoorDynPoint point, unsigned int* n);
int DECLDIR MoorDyn_GetPointAttached(MoorDynPoint point, unsigned int i, MoorDynLine* l,
                                     int* e);
int DECLDIR MoorDyn_SavePointVTK(MoorDynPoint point, const char* filename);

int DECLDIR MoorDyn_GetRodID(MoorDynRod l, int* id);
int DECLDIR MoorDyn_GetRodType(MoorDynRod l, int* t);
int DECLDIR MoorDyn_GetRodForce(MoorDynRod l, double f[6]);
int DECLDIR MoorDyn_GetRodM(MoorDynRod l, double m[6][6]);
int DECLDIR MoorDyn_GetRodN(MoorDynRod l, unsigned int* n);
int DECLDIR MoorDyn_GetRodNumberNodes(MoorDynRod l, unsigned int* n);
int DECLDIR MoorDyn_GetRodNodePos(MoorDynRod l, unsigned int i, double pos[3]);
int DECLDIR MoorDyn_GetRodNodeVel(MoorDynRod l, unsigned int i, double vel[3]);
int DECLDIR MoorDyn_SaveRodVTK(MoorDynRod l, const char* filename);

int DECLDIR MoorDyn_GetBodyID(MoorDynBody body, int* id);
int DECLDIR MoorDyn_GetBodyState(MoorDynBody body, double r[6], double rd[6]);
int DECLDIR MoorDyn_GetBodyType(MoorDynBody b, int* t);
int DECLDIR MoorDyn_GetBodyPos(MoorDynBody b, double r[3]);
int DECLDIR MoorDyn_GetBodyAngle(MoorDynBody b, double r[3]);
int DECLDIR MoorDyn_GetBodyVel(MoorDynBody b, double rd[3]);
int DECLDIR MoorDyn_GetBodyAngVel(MoorDynBody b, double rd[3]);
int DECLDIR MoorDyn_GetBodyForce(MoorDynBody b, double f[6]);
int DECLDIR MoorDyn_GetBodyM(MoorDynBody b, double m[6][6]);
int DECLDIR MoorDyn_SaveBodyVTK(MoorDynBody b, const char* filename);

int DECLDIR MoorDyn_GetWavesKin(MoorDynWaves waves, double x, double y, double z,
                                double U[3], double Ud[3], double* zeta, double* PDyn,
                                MoorDynSeafloor seafloor);
int DECLDIR MoorDyn_GetDepthAt(MoorDynSeafloor seafloor, double x, double y,
                               double* depth);
int DECLDIR MoorDyn_GetAverageDepth(MoorDynSeafloor seafloor, double* avgDepth);
int DECLDIR MoorDyn_GetMinDepth(MoorDynSeafloor seafloor, double* minDepth);
double DECLDIR WaveNumber(double Omega, double g, double h);

#ifdef __cplusplus
}
#endif

#endif
