"""librodyn (docs/capi.md) loaded in process with ctypes: the C functions of MoorDyn's
C API as rodyn serves them, with their argument and result types declared.

The library is looked for, in this order: the path in the environment variable
RODYN_LIB; build/librodyn.so of the repository this package is in (an editable
install, tools/setup.sh); the system's library path (``cmake --install``)."""
import ctypes
import ctypes.util
import os

_lib = None

_P = ctypes.c_void_p
_D = ctypes.POINTER(ctypes.c_double)
_U = ctypes.POINTER(ctypes.c_uint)
_I = ctypes.POINTER(ctypes.c_int)
_F = ctypes.POINTER(ctypes.c_float)
_SIGNATURES = {
    "MoorDyn_Create": (_P, [ctypes.c_char_p]),
    "MoorDyn_NCoupledDOF": (ctypes.c_int, [_P, _U]),
    "MoorDyn_SetVerbosity": (ctypes.c_int, [_P, ctypes.c_int]),
    "MoorDyn_SetLogLevel": (ctypes.c_int, [_P, ctypes.c_int]),
    "MoorDyn_Init": (ctypes.c_int, [_P, _D, _D]),
    "MoorDyn_Init_NoIC": (ctypes.c_int, [_P, _D, _D]),
    "MoorDyn_Step": (ctypes.c_int, [_P, _D, _D, _D, _D, _D]),
    "MoorDyn_Close": (ctypes.c_int, [_P]),
    "MoorDyn_GetNumberLines": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetNumberPoints": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetLine": (_P, [_P, ctypes.c_uint]),
    "MoorDyn_GetPoint": (_P, [_P, ctypes.c_uint]),
    "MoorDyn_GetNumberBodies": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetBody": (_P, [_P, ctypes.c_uint]),
    "MoorDyn_GetBodyID": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetBodyState": (ctypes.c_int, [_P, _D, _D]),
    "MoorDyn_GetFASTtens": (ctypes.c_int, [_P, _I, _F, _F, _F, _F]),
    "MoorDyn_BreakLine": (ctypes.c_int, [_P, _P, _P]),
    "MoorDyn_GetLineID": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetLineN": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetLineNumberNodes": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetLineUnstretchedLength": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetLineNodePos": (ctypes.c_int, [_P, ctypes.c_uint, _D]),
    "MoorDyn_GetLineNodeTen": (ctypes.c_int, [_P, ctypes.c_uint, _D]),
    "MoorDyn_GetLineNodeVel": (ctypes.c_int, [_P, ctypes.c_uint, _D]),
    "MoorDyn_GetLineMaxTen": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetLineNodeCurv": (ctypes.c_int, [_P, ctypes.c_uint, _D]),
    "MoorDyn_GetLineFairTen": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetPointID": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetPointType": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetPointPos": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetPointForce": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetPointVel": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetPointNAttached": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetPointAttached": (ctypes.c_int, [_P, ctypes.c_uint, ctypes.POINTER(_P), _I]),
    "MoorDyn_GetBodyType": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetBodyPos": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetBodyAngle": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetBodyVel": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetBodyAngVel": (ctypes.c_int, [_P, _D]),
    "MoorDyn_IsLineConstantEA": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetLineConstantEA": (ctypes.c_int, [_P, _D]),
    "MoorDyn_GetDt": (ctypes.c_int, [_P, _D]),
    "MoorDyn_SetDt": (ctypes.c_int, [_P, ctypes.c_double]),
    "MoorDyn_GetCFL": (ctypes.c_int, [_P, _D]),
    "MoorDyn_SetCFL": (ctypes.c_int, [_P, ctypes.c_double]),
    "MoorDyn_GetTimeScheme": (ctypes.c_int, [_P, ctypes.c_char_p,
                                             ctypes.POINTER(ctypes.c_size_t)]),
    "MoorDyn_SetTimeScheme": (ctypes.c_int, [_P, ctypes.c_char_p]),
    "MoorDyn_Save": (ctypes.c_int, [_P, ctypes.c_char_p]),
    "MoorDyn_Load": (ctypes.c_int, [_P, ctypes.c_char_p]),
    "MoorDyn_GetNumberRods": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetRod": (_P, [_P, ctypes.c_uint]),
    "MoorDyn_GetRodID": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetRodType": (ctypes.c_int, [_P, _I]),
    "MoorDyn_GetRodN": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetRodNumberNodes": (ctypes.c_int, [_P, _U]),
    "MoorDyn_GetRodNodePos": (ctypes.c_int, [_P, ctypes.c_uint, _D]),
    "MoorDyn_GetRodNodeVel": (ctypes.c_int, [_P, ctypes.c_uint, _D]),
    "MoorDyn_ExternalWaveKinInit": (ctypes.c_int, [_P, _U]),
    "MoorDyn_ExternalWaveKinGetN": (ctypes.c_int, [_P, _U]),
    "MoorDyn_ExternalWaveKinGetCoordinates": (ctypes.c_int, [_P, _D]),
    "MoorDyn_ExternalWaveKinSet": (ctypes.c_int, [_P, _D, _D, ctypes.c_double]),
}


def _candidates():
    if os.environ.get("RODYN_LIB"):
        yield os.environ["RODYN_LIB"]
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    yield os.path.join(repo, "build", "librodyn.so")
    found = ctypes.util.find_library("rodyn")
    if found:
        yield found


def lib():
    """The loaded librodyn, its functions typed (OSError when it is not found)."""
    global _lib
    if _lib is not None:
        return _lib
    tried = []
    for path in _candidates():
        tried.append(path)
        if os.path.sep in path and not os.path.exists(path):
            continue
        try:
            handle = ctypes.CDLL(path)
        except OSError:
            continue
        for name, (res, args) in _SIGNATURES.items():
            fn = getattr(handle, name)
            fn.restype = res
            fn.argtypes = args
        _lib = handle
        return _lib
    raise OSError("librodyn not found (tried: " + ", ".join(tried) + "); build rodyn "
                  "(README.md) or set RODYN_LIB to the path of librodyn.so")


def doubles(values, n=None):
    """A C array of doubles holding values (n zeros when values is None); an empty one
    is a NULL pointer (no coupled DOFs)."""
    if values is None:
        return (ctypes.c_double * n)()
    values = [float(v) for v in values]
    if not values:
        return None
    return (ctypes.c_double * len(values))(*values)
