#!/usr/bin/env python3
"""Checked writes in one place: every file write of src/ goes through one module.

usage: check_writes_one_place.py SOURCE_DIR

Every byte rodyn writes to a file goes through rodyn_outfile (write(2), close(2),
ftruncate(2), rename(2): every call checked) or the HDF5 layer, rodyn_hdf5 (every HDF5
call checked), so a full disk or a failed close is seen wherever it happens. Checks, over
src/**/*.f90 and the fypp templates src/**/*.fypp the build generates Fortran from:
  1. every Fortran OPEN (continuation lines joined) is ACTION='READ', but the lock of
     rodyn_outdir (STATUS='NEW', ACTION='WRITE': an exclusive create, closed at once;
     its content is written through rodyn_outfile);
  2. the C file calls (open, write, pwrite, close, ftruncate, rename, unlink, fsync,
     creat, fopen, fwrite) are bound only in rodyn_outfile.f90;
  3. HDF5 is called (CALL H5...) only in the HDF5 layer's files: rodyn_hdf5.f90,
     rodyn_hdf5_base.f90 and the template rodyn_hdf5_arrays.fypp.
"""
import pathlib
import re
import sys

C_FILE_CALLS = ("open", "write", "pwrite", "close", "ftruncate", "rename", "unlink",
                "fsync", "creat", "fopen", "fwrite")
HDF5_LAYER = ("rodyn_hdf5.f90", "rodyn_hdf5_base.f90", "rodyn_hdf5_arrays.fypp")


def statements(text):
    """The Fortran statements of a free-form source, comments dropped and '&'
    continuations joined."""
    out, pending = [], ""
    for line in text.splitlines():
        code = re.sub(r"!.*$", "", line).rstrip() if "'" not in line else line.rstrip()
        if code.lstrip().startswith("!"):
            continue
        code = code.lstrip()
        if pending:
            code = pending + " " + code.lstrip("&").lstrip()
        if code.endswith("&"):
            pending = code[:-1].rstrip()
            continue
        pending = ""
        out.append(code)
    return out


def main():
    src = pathlib.Path(sys.argv[1]).resolve() / "src"
    problems, opens, binds, hdf5 = [], 0, 0, 0
    for path in sorted(src.rglob("*.f90")) + sorted(src.rglob("*.fypp")):
        name = path.name
        for stmt in statements(path.read_text()):
            low = stmt.lower().replace(" ", "")
            if re.search(r"(^|\))open\(", low):
                opens += 1
                lock = (name == "rodyn_outdir.f90" and "status='new'" in low
                        and "action='write'" in low)
                if "action='read'" not in low and not lock:
                    problems.append(f"{path}: OPEN not for reading: {stmt}")
            for m in re.finditer(r"bind\(c,name=['\"](\w+)['\"]\)", low):
                if m.group(1) in C_FILE_CALLS:
                    binds += 1
                    if name != "rodyn_outfile.f90":
                        problems.append(f"{path}: binds C's {m.group(1)}: {stmt}")
            if re.search(r"(^|\))callh5", low):
                hdf5 += 1
                if name not in HDF5_LAYER:
                    problems.append(f"{path}: calls HDF5 outside rodyn_hdf5: {stmt}")
    for p in problems:
        print("FAIL: " + p)
    if problems:
        sys.exit(1)
    if not (opens and binds and hdf5):
        print(f"FAIL: found {opens} OPEN, {binds} C file calls, {hdf5} HDF5 calls in {src}")
        sys.exit(1)
    print(f"{opens} OPEN statements: all for reading but the lock's exclusive create; "
          f"{binds} C file calls bound, all in rodyn_outfile.f90; {hdf5} HDF5 calls, all "
          "in the HDF5 layer (" + ", ".join(HDF5_LAYER) + ")")
    print("OK")


if __name__ == "__main__":
    main()
