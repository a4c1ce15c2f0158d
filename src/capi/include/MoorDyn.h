/* librodyn: MoorDyn's first C API (one system per program), as MoorDyn v2.7 declares
 * it (its source/MoorDyn.h); docs/capi.md lists what librodyn implements. */
#ifndef __MOORDYN_H__
#define __MOORDYN_H__

#include "MoorDynAPI.h"

#ifdef __cplusplus
extern "C"
{
#endif

int DECLDIR MoorDynInit(const double x[], const double xd[], const char* infilename);
int DECLDIR MoorDynStep(const double x[], const double xd[], double f[], double* t,
                        double* dt);
int DECLDIR MoorDynClose(void);
int DECLDIR externalWaveKinInit();
void DECLDIR getWaveKinCoordinates(double r_out[]);
void DECLDIR setWaveKin(const double U_in[], const double Ud_in[], double t_in);
double DECLDIR GetFairTen(int);
int DECLDIR GetFASTtens(int* numLines, float FairHTen[], float FairVTen[],
                        float AnchHTen[], float AnchVTen[]);
int DECLDIR GetPointPos(int l, double pos[3]);
int DECLDIR GetPointForce(int l, double force[3]);
int DECLDIR GetNodePos(int LineNum, int NodeNum, double pos[3]);
void DECLDIR AllOutput(double, double);
void DECLDIR SetDisableConsole(int disable);

#ifdef __cplusplus
}
#endif

#endif
