"""MoorDyn's Python functions (its PyPI package ``moordyn``, v2.x) over librodyn: a
script written for ``moordyn`` runs on rodyn by changing its import to
``import rodyn.moordyn as moordyn`` (docs/python.md). The functions of librodyn
(docs/capi.md) are here with MoorDyn's names, arguments and results; a system, line or
point is an opaque handle, as MoorDyn's are.

MoorDyn_Create with no file reads "Mooring/lines.txt", MoorDyn's default."""
import ctypes

from ._lib import lib, doubles

__all__ = ["Create", "NCoupledDOF", "SetVerbosity", "SetLogLevel", "Init", "Init_NoIC",
           "Step", "Close", "Save", "Load",
           "GetNumberLines", "GetLine", "GetNumberPoints", "GetPoint", "GetNumberBodies",
           "GetBody", "GetBodyID", "GetBodyState", "GetFASTtens", "BreakLine",
           "GetLineID", "GetLineN", "GetLineNumberNodes", "GetLineUnstretchedLength",
           "GetLineNodePos", "GetLineNodeVel", "GetLineNodeTen", "GetLineMaxTen", "GetLineNodeCurv", "GetLineFairTen",
           "GetPointID", "GetPointType", "GetPointPos", "GetPointForce", "GetPointVel",
           "GetPointNAttached", "GetPointAttached", "GetBodyType", "GetBodyPos",
           "GetBodyAngle", "GetBodyVel", "GetBodyAngVel", "IsLineConstantEA",
           "GetLineConstantEA", "GetDt", "SetDt", "GetCFL", "SetCFL", "GetTimeScheme",
           "SetTimeScheme", "ExternalWaveKinInit", "ExternalWaveKinGetN",
           "ExternalWaveKinGetCoordinates", "GetWaveKinCoordinates", "ExternalWaveKinSet",
           "SetWaveKin", "GetNumberRods", "GetRod", "GetRodID", "GetRodType", "GetRodN",
           "GetRodNumberNodes", "GetRodNodePos", "GetRodNodeVel"]

DEFAULT_FILE = "Mooring/lines.txt"


def Create(filepath=""):
    """The system of a MoorDyn v2 input file (None when it cannot be read)."""
    h = lib().MoorDyn_Create((filepath or DEFAULT_FILE).encode())
    return h or None


def _uint(fn, handle):
    n = ctypes.c_uint(0)
    code = fn(handle, ctypes.byref(n))
    return n.value if code == 0 else code


def NCoupledDOF(instance):
    return _uint(lib().MoorDyn_NCoupledDOF, instance)


def SetVerbosity(instance, verbosity):
    return lib().MoorDyn_SetVerbosity(instance, int(verbosity))


def SetLogLevel(instance, verbosity):
    return lib().MoorDyn_SetLogLevel(instance, int(verbosity))


def Init(instance, x, v):
    """Coupled points at x, the statics solved: 0 on success, else MoorDyn's code."""
    return lib().MoorDyn_Init(instance, doubles(list(x)), doubles(list(v)))


def Init_NoIC(instance, x, v):
    """As Init, without the statics: the dynamics start from the lines' starting shapes."""
    return lib().MoorDyn_Init_NoIC(instance, doubles(list(x)), doubles(list(v)))


def Save(instance, filepath):
    """The system's state after its last step to filepath (HDF5); MoorDyn's code."""
    return lib().MoorDyn_Save(instance, str(filepath).encode())


def Load(instance, filepath):
    """The state Save wrote, into a system of the same file after Init_NoIC (or Init);
    MoorDyn's code."""
    return lib().MoorDyn_Load(instance, str(filepath).encode())


def Step(instance, x, v, t, dt):
    """A coupling step: the forces on the coupled DOFs at its end, as a tuple."""
    n = NCoupledDOF(instance)
    f = doubles(None, max(n, 1))
    tt, hh = ctypes.c_double(t), ctypes.c_double(dt)
    code = lib().MoorDyn_Step(instance, doubles(list(x)), doubles(list(v)), f,
                              ctypes.byref(tt), ctypes.byref(hh))
    if code != 0:
        raise RuntimeError(f"MoorDyn_Step: librodyn code {code} (the message is on stderr)")
    return tuple(f[:n])


def Close(instance):
    return lib().MoorDyn_Close(instance)


def BreakLine(instance, point, line):
    """The line leaves the point at the start of the next step; raises on an error."""
    code = lib().MoorDyn_BreakLine(instance, point, line)
    if code != 0:
        raise RuntimeError(f"MoorDyn_BreakLine: librodyn code {code} (the message is on stderr)")


def GetNumberLines(instance):
    return _uint(lib().MoorDyn_GetNumberLines, instance)


def GetNumberPoints(instance):
    return _uint(lib().MoorDyn_GetNumberPoints, instance)


def GetLine(instance, line):
    return lib().MoorDyn_GetLine(instance, int(line)) or None


def GetPoint(instance, point):
    return lib().MoorDyn_GetPoint(instance, int(point)) or None


def GetNumberBodies(instance):
    return _uint(lib().MoorDyn_GetNumberBodies, instance)


def GetBody(instance, body):
    return lib().MoorDyn_GetBody(instance, int(body)) or None


def GetBodyID(instance):
    return _int(lib().MoorDyn_GetBodyID, instance)


def GetBodyState(instance):
    """The body's position and angles r, p, y, and their rates, as two tuples."""
    r, rd = doubles(None, 6), doubles(None, 6)
    lib().MoorDyn_GetBodyState(instance, r, rd)
    return tuple(r[:]), tuple(rd[:])


def GetFASTtens(instance, n_lines):
    """Fairlead horizontal and vertical, anchor horizontal and vertical tensions [N]."""
    arrays = [(ctypes.c_float * n_lines)() for _ in range(4)]
    n = ctypes.c_int(n_lines)
    lib().MoorDyn_GetFASTtens(instance, ctypes.byref(n), *arrays)
    return tuple(list(a) for a in arrays)


def _int(fn, handle):
    n = ctypes.c_int(0)
    code = fn(handle, ctypes.byref(n))
    return n.value if code == 0 else code


def GetLineID(instance):
    return _int(lib().MoorDyn_GetLineID, instance)


def GetLineN(instance):
    return _uint(lib().MoorDyn_GetLineN, instance)


def GetLineNumberNodes(instance):
    return _uint(lib().MoorDyn_GetLineNumberNodes, instance)


def _double(fn, *args):
    x = ctypes.c_double(0.0)
    fn(*args, ctypes.byref(x))
    return x.value


def GetLineUnstretchedLength(instance):
    return _double(lib().MoorDyn_GetLineUnstretchedLength, instance)


def _vec(fn, *args):
    v = doubles(None, 3)
    fn(*args, v)
    return tuple(v[:])


def GetLineNodePos(instance, i):
    return _vec(lib().MoorDyn_GetLineNodePos, instance, int(i))


def GetLineNodeVel(instance, i):
    return _vec(lib().MoorDyn_GetLineNodeVel, instance, int(i))


def GetLineMaxTen(instance):
    return _double(lib().MoorDyn_GetLineMaxTen, instance)


def GetLineNodeTen(instance, i):
    return _vec(lib().MoorDyn_GetLineNodeTen, instance, int(i))


def GetLineNodeCurv(instance, i):
    return _double(lib().MoorDyn_GetLineNodeCurv, instance, int(i))


def GetLineFairTen(instance):
    return _double(lib().MoorDyn_GetLineFairTen, instance)


def GetPointID(instance):
    return _int(lib().MoorDyn_GetPointID, instance)


def GetPointType(instance):
    return _int(lib().MoorDyn_GetPointType, instance)


def GetPointPos(instance):
    return _vec(lib().MoorDyn_GetPointPos, instance)


def GetPointForce(instance):
    return _vec(lib().MoorDyn_GetPointForce, instance)


def GetPointVel(instance):
    return _vec(lib().MoorDyn_GetPointVel, instance)


def GetPointNAttached(instance):
    return _uint(lib().MoorDyn_GetPointNAttached, instance)


def GetPointAttached(instance, i):
    """Line end i (from 0) on the point: its line's handle and the end (0 A, 1 B)."""
    line, end = ctypes.c_void_p(), ctypes.c_int(0)
    code = lib().MoorDyn_GetPointAttached(instance, int(i), ctypes.byref(line),
                                          ctypes.byref(end))
    if code != 0:
        raise RuntimeError(f"MoorDyn_GetPointAttached: librodyn code {code}")
    return line.value, end.value


def GetBodyType(instance):
    return _int(lib().MoorDyn_GetBodyType, instance)


def GetBodyPos(instance):
    return _vec(lib().MoorDyn_GetBodyPos, instance)


def GetBodyAngle(instance):
    return _vec(lib().MoorDyn_GetBodyAngle, instance)


def GetBodyVel(instance):
    return _vec(lib().MoorDyn_GetBodyVel, instance)


def GetBodyAngVel(instance):
    return _vec(lib().MoorDyn_GetBodyAngVel, instance)


def IsLineConstantEA(instance):
    return bool(_int(lib().MoorDyn_IsLineConstantEA, instance))


def GetLineConstantEA(instance):
    return _double(lib().MoorDyn_GetLineConstantEA, instance)


def GetDt(instance):
    return _double(lib().MoorDyn_GetDt, instance)


def SetDt(instance, dt):
    return lib().MoorDyn_SetDt(instance, float(dt))


def GetCFL(instance):
    return _double(lib().MoorDyn_GetCFL, instance)


def SetCFL(instance, cfl):
    return lib().MoorDyn_SetCFL(instance, float(cfl))


def GetTimeScheme(instance):
    n = ctypes.c_size_t(0)
    lib().MoorDyn_GetTimeScheme(instance, None, ctypes.byref(n))
    buf = ctypes.create_string_buffer(n.value)
    lib().MoorDyn_GetTimeScheme(instance, buf, None)
    return buf.value.decode()


def SetTimeScheme(instance, name):
    return lib().MoorDyn_SetTimeScheme(instance, name.encode())


def ExternalWaveKinInit(instance):
    """0 when the system takes the water's kinematics from the script (WaveKin 1);
    raises otherwise."""
    n = ctypes.c_uint(0)
    code = lib().MoorDyn_ExternalWaveKinInit(instance, ctypes.byref(n))
    if code != 0:
        raise RuntimeError(f"MoorDyn_ExternalWaveKinInit: librodyn code {code}")
    return code


def ExternalWaveKinGetN(instance):
    """The number of places where the water's kinematics are given."""
    return _uint(lib().MoorDyn_ExternalWaveKinGetN, instance)


def ExternalWaveKinGetCoordinates(instance):
    """The places, as a list of [x, y, z] [m]."""
    n = ExternalWaveKinGetN(instance)
    r = doubles(None, 3 * max(n, 1))
    code = lib().MoorDyn_ExternalWaveKinGetCoordinates(instance, r)
    if code != 0:
        raise RuntimeError(f"MoorDyn_ExternalWaveKinGetCoordinates: librodyn code {code}")
    return [list(r[3 * i:3 * i + 3]) for i in range(n)]


GetWaveKinCoordinates = ExternalWaveKinGetCoordinates


def ExternalWaveKinSet(instance, u, a, t):
    """The water's velocity u and acceleration a at the places (lists of triples), at
    time t: 0 on success, else MoorDyn's code."""
    uu = [c for p in u for c in p]
    aa = [c for p in a for c in p]
    return lib().MoorDyn_ExternalWaveKinSet(instance, doubles(uu), doubles(aa), float(t))


SetWaveKin = ExternalWaveKinSet


def GetNumberRods(instance):
    return _uint(lib().MoorDyn_GetNumberRods, instance)


def GetRod(instance, rod):
    return lib().MoorDyn_GetRod(instance, int(rod)) or None


def GetRodID(instance):
    return _int(lib().MoorDyn_GetRodID, instance)


def GetRodType(instance):
    return _int(lib().MoorDyn_GetRodType, instance)


def GetRodN(instance):
    return _uint(lib().MoorDyn_GetRodN, instance)


def GetRodNumberNodes(instance):
    return _uint(lib().MoorDyn_GetRodNumberNodes, instance)


def GetRodNodePos(instance, i):
    return _vec(lib().MoorDyn_GetRodNodePos, instance, int(i))


def GetRodNodeVel(instance, i):
    return _vec(lib().MoorDyn_GetRodNodeVel, instance, int(i))
