#!/usr/bin/env python3
"""One description of the output tables (rodyn_output_schema, docs/output.md).

usage: check_output_schema.py SCHEMA_DUMP SOURCE_DIR WORK_DIR RODYN

rodyn_output_schema (printed by SCHEMA_DUMP) names every column of every CSV table and
every HDF5 dataset (but /environment's) with its unit and meaning. Checks:
  1. the header row the writers take from it is its columns, in order;
  2. docs/output.md documents exactly those tables and, under each table's heading,
     exactly those columns, in the same order, with the same units (environment.csv:
     its header quoted in the text); and in the layouts of results.h5 and dynamic.h5
     exactly the datasets of the schema, with the same units;
  3. the Python readers' copy (postproc/rodyn_post/schema.py, made by
     tools/gen_output_schema.py) is the schema, and the readers look only for columns
     the schema has, in its order;
  4. a run of RODYN (statics, dynamics, water; CSV and HDF5) writes every table of the
     schema with that header; results.h5 and dynamic.h5 hold exactly the datasets of
     the schema (and /environment), each with the attributes `units` and `description`,
     equal to the schema's;
  5. the keys of status.txt (rodyn_output_schema's status_keys): docs/output.md's key
     tables (status.txt, of a dynamic run) list exactly them (parameter.NAME in the
     text), schema.py has them (STATUS), and the run's status.txt writes only them, in
     their order (NAME: a table's or a parameter's name);
  6. the /environment datasets (environment_datasets): the run's results.h5 and
     dynamic.h5 (a deck with a current and a seabed) write exactly them with the
     schema's units and description; docs/output.md's Environment table gives each the
     same unit (current_z as current_z_<k>); schema.py has them (ENVIRONMENT);
  7. the attributes of groups (and end_held) of the run's results.h5 and dynamic.h5 are
     exactly those of output_attributes (schema.py: ATTRIBUTES), and docs/output.md's
     layouts of the two files name exactly those attributes, with the schema's unit
     where it has one; its text states the `units` and `description` of every dataset.
"""
import pathlib
import re
import shutil
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def read_schema(dump):
    out = subprocess.run([dump], capture_output=True, text=True, check=True).stdout
    columns, headers, datasets = {}, {}, {}
    status = []
    environment, attributes = {}, {}
    for line in out.splitlines():
        kind, *fields = line.split("\t")
        if kind == "COLUMN":
            file, name, unit, meaning = fields
            if not meaning:
                fail(f"{file} {name}: no meaning in the schema")
            columns.setdefault(file, []).append((name, unit))
        elif kind == "HEADER":
            headers[fields[0]] = fields[1]
        elif kind == "DATASET":
            file, path, units, description = fields
            if not description:
                fail(f"{file} {path}: no description in the schema")
            datasets.setdefault(file, {})[path] = (units, description)
        elif kind == "STATUS":
            key, unit, meaning = fields
            if not meaning or not unit:
                fail(f"status.txt {key}: no unit or meaning in the schema")
            status.append((key, unit, meaning))
        elif kind == "ENVIRONMENT":
            files, path, units, description = fields
            if files != "results.h5, dynamic.h5" or not description:
                fail(f"{path}: files {files!r} or no description in the schema")
            environment[path] = (units, description)
        elif kind == "ATTRIBUTE":
            file, name, unit, meaning = fields
            if not meaning or not unit or ":" not in name:
                fail(f"{file} {name}: no unit or meaning, or not object:attribute")
            attributes.setdefault(file, {})[name] = (unit, meaning)
    return columns, headers, datasets, status, environment, attributes


def python_schema(src):
    """postproc's generated schema module (rodyn_post.schema) of the source tree src."""
    sys.path.insert(0, str(src / "postproc"))
    from rodyn_post import schema
    return schema


def check_generated(what, ours, generated):
    """One part of the schema as the Fortran dump gives it against rodyn_post.schema's."""
    if ours != generated:
        fail(f"postproc/rodyn_post/schema.py: {what} differs from the schema: run "
             "python3 tools/gen_output_schema.py")


def check_attributes(src, attributes, out):
    """The attributes of the run's HDF5 files against the schema's."""
    import h5py
    check_generated("ATTRIBUTES", attributes, python_schema(src).ATTRIBUTES)
    for name in ("results.h5", "dynamic.h5"):
        found = set()

        def visit(path, obj):
            for a in obj.attrs:
                if isinstance(obj, h5py.Dataset) and a in ("units", "description"):
                    continue
                key = re.sub(r"^/(static|dynamic)/(LEG|TETHER)(/|$)", r"/\1/LINE\3", path)
                found.add(f"{key}:{'NAME' if key == '/parameters' else a}")
        with h5py.File(out / name, "r") as f:
            visit("/", f)
            f.visititems(lambda p, o: visit("/" + p, o))
        if found != set(attributes[name]):
            fail(f"{out / name}: attributes differ from the schema: not written "
                 f"{set(attributes[name]) - found}, not in the schema "
                 f"{found - set(attributes[name])}")
        print(f"{name}: its {len(found)} attributes are the schema's")


def layout_block(text, heading):
    """The first code block (```) after `heading` in docs/output.md: an HDF5 layout."""
    start = text.index("\n" + heading + "\n")
    begin = text.index("```\n", start) + 4
    return text[begin:text.index("```", begin)]


ATTRIBUTE_NAMES = re.compile(r"\battributes? ([a-z][a-z0-9_]*(?:, [a-z][a-z0-9_]*)*)"
                             r"(?![a-z0-9_])")


def doc_layout_attributes(block):
    """{'object:attribute': text} of the attributes a layout of docs/output.md gives:
    the indented lines under an object line ending 'attributes:' or '...:' after
    'attributes' (names before a space), 'attribute NAME[, NAME]' in an object's text
    or its continuation lines, and 'one attribute per deck parameter' (NAME); an
    object's text 'as in results.h5' (no attributes of its own) is marked REF. The text
    of an attribute is what follows its names on that line (its type, unit, meaning)."""
    out, group, current, listing, group_text = {}, None, None, False, ""

    def inline(obj, line):
        if "attribute per deck" in line:
            out[f"{obj}:NAME"] = line
        for m in ATTRIBUTE_NAMES.finditer(line):
            if m.group(1) == "per":
                continue
            for name in m.group(1).split(", "):
                out[f"{obj}:{name}"] = line[m.end():]

    for line in block.splitlines():
        if line.startswith("/"):
            current = group = line.replace("<LINE NAME>", "LINE").split()[0]
            group_text = line
            listing = line.rstrip().endswith(":") and "attributes" in line
            inline(current, line)
            if "as in results.h5" in line:
                out[f"{current}:REF"] = line
            continue
        member = re.match(r"^    ([a-z][a-z0-9_]*)(?:, [a-z][a-z0-9_]*)*\s+\(", line)
        if member and group:
            current, listing = group + "/" + member.group(1), False
            inline(current, line)
        elif line.startswith(" " * 30) and current:
            inline(current, line)
            listing = listing or (current == group and line.rstrip().endswith(":")
                                  and "attributes" in group_text)
        elif listing and line.startswith("    "):
            m = re.match(r"^    ([a-z][a-z0-9_]*(?:, [a-z][a-z0-9_]*)*)(\s+|$)", line)
            if m:
                for name in m.group(1).split(", "):
                    out[f"{current}:{name}"] = line[m.end():]
    return out


def check_docs_attributes(src, attributes):
    """docs/output.md's layouts of results.h5 and dynamic.h5 (and the Environment block
    for /environment) name exactly the attributes of output_attributes, each with its
    unit where it has one ('[u]' or ', u,' in its text); an object of dynamic.h5 'as in
    results.h5' takes results.h5's. Every dataset's `units` and `description` are stated
    in both sections."""
    text = (src / "docs" / "output.md").read_text()
    environment = doc_layout_attributes(layout_block(text, "## Environment"))
    docs = {}
    for file, heading in (("results.h5", "## results.h5"), ("dynamic.h5", "### dynamic.h5")):
        found = doc_layout_attributes(layout_block(text, heading))
        if "/environment:REF" in found or file == "results.h5":
            found.update(environment)
        for ref in [k for k in found if k.endswith(":REF")]:
            obj = ref[:-len(":REF")]
            found.update({k: v for k, v in docs["results.h5"].items()
                          if k.startswith(obj + ":")})
            del found[ref]
        docs[file] = found
        schema = attributes[file]
        if set(found) != set(schema):
            fail(f"docs/output.md, {file}: attributes differ from the schema "
                 f"(output_attributes): not documented {sorted(set(schema) - set(found))}, "
                 f"not in the schema {sorted(set(found) - set(schema))}")
        for name, (unit, _) in schema.items():
            if unit != "-" and not re.search(
                    r"(\[" + re.escape(unit) + r"\]|[,(:]\s*" + re.escape(unit) + r"\s*[,)])",
                    found[name]):
                fail(f"docs/output.md, {file}: attribute {name} is in {unit} (the schema); "
                     f"its text {found[name].strip()!r} does not say so")
        print(f"docs/output.md: the {len(found)} attributes of {file} as in the schema")
    section = text[text.index("\n## results.h5\n"):text.index("\n## Dynamic runs\n")]
    dynamic = text[text.index("\n### dynamic.h5\n"):]
    if ("two string attributes: `units`" not in section or "`description`" not in section
            or "a `units` and a `description`\nattribute on every dataset" not in dynamic):
        fail("docs/output.md: the `units` and `description` attributes of every dataset "
             "are not stated for results.h5 and dynamic.h5")


def check_environment(src, environment, out):
    """The /environment datasets of a run and of docs/output.md against the schema."""
    import h5py
    check_generated("ENVIRONMENT", environment, python_schema(src).ENVIRONMENT)
    for name in ("results.h5", "dynamic.h5"):
        with h5py.File(out / name, "r") as f:
            found = {"/environment/" + k: (str(d.attrs["units"]), str(d.attrs["description"]))
                     for k, d in f["environment"].items()}
        if found != environment:
            fail(f"{out / name}: /environment differs from the schema: not written "
                 f"{set(environment) - set(found)}, not in the schema "
                 f"{set(found) - set(environment)}, other attributes "
                 f"{[k for k in found if k in environment and found[k] != environment[k]]}")
    text = (src / "docs" / "output.md").read_text()
    start = text.index("\n## Environment\n")
    table = {}
    for line in text[start:text.index("\n## ", start + 1)].splitlines():
        m = re.match(r"^\| `([a-z_]+?)(_<k>)?`\s*\|\s*([^|]+?)\s*\|", line)
        if m:
            table[m.group(1)] = m.group(3)
    other = {p: u for p, (u, _) in environment.items()
             if table.get(p.rsplit("/", 1)[1]) != u}
    if other:
        fail(f"docs/output.md, Environment: units differ from the schema's: {other}")
    print(f"/environment: {len(environment)} datasets in the schema, written with its "
          "units and descriptions in results.h5 and dynamic.h5, documented")


def status_key_pattern(status):
    """One regular expression per key of the schema (NAME: any name)."""
    return [re.compile("^" + re.escape(k).replace("NAME", ".+") + "$") for k, _, _ in status]


def check_status(src, status, out):
    """docs/output.md's status.txt key tables and a run's status.txt against the schema."""
    text = (src / "docs" / "output.md").read_text()
    keys = [k for k, _, _ in status]
    documented = []
    for heading in ("## status.txt", "### status.txt of a dynamic run"):
        start = text.index("\n" + heading + "\n")
        end = text.find("\n#", start + 1)
        in_table = False
        for line in text[start:end].splitlines():
            if line.startswith("| key"):
                in_table = True
                continue
            if in_table and line.startswith("|"):
                documented += re.findall(r"^\| `([^`]+)`", line)
            elif in_table:
                in_table = False
    documented = [k for k in documented if not k.startswith("-")]
    missing = [k for k in keys if k not in documented and not k.startswith("parameter.")]
    extra = [k for k in documented if k not in keys]
    if missing or extra:
        fail(f"docs/output.md: status.txt keys differ from the schema: not documented "
             f"{missing}, not in the schema {extra}")
    if "`parameter.NAME = text`" not in text:
        fail("docs/output.md: the key parameter.NAME of status.txt is not documented")
    check_generated("STATUS", tuple(status), tuple(python_schema(src).STATUS))
    patterns = status_key_pattern(status)
    last = -1
    written = [line.partition(" = ")[0] for line in (out / "status.txt").read_text()
               .splitlines()]
    for key in written:
        hits = [i for i, p in enumerate(patterns) if p.match(key)]
        if not hits:
            fail(f"{out / 'status.txt'}: key {key!r} is not in the schema")
        if hits[0] < last:
            fail(f"{out / 'status.txt'}: key {key!r} out of the schema's order")
        last = hits[0]
    print(f"status.txt: {len(keys)} keys in the schema, documented; a run writes "
          f"{len(written)} keys, all of the schema, in its order")


def plain_units(units):
    """Units without their parenthesised column notes: 'N (columns 1-3), N m (4-6)'
    -> 'N, N m' (as docs/output.md writes them)."""
    return re.sub(r"\s+", " ", re.sub(r"\s*\([^)]*\)", "", units)).strip()


def doc_datasets(section):
    """{path: units} of the datasets in the layout (code block) of an HDF5 file in a
    section of docs/output.md: top-level lines '/path  (shape)  units  ...' and member
    lines '    name[, name]  (shape)  units  ...' of the group line above them ('<LINE
    NAME>' read as LINE); /deck is a string dataset without shape or units."""
    out, group = {}, None
    for line in section.splitlines():
        if line.startswith("/"):
            group = line.split()[0].replace("<LINE", "LINE")
            if group.startswith("/deck"):
                out["/deck"] = "-"
            m = re.match(r"^(/\S+)\s+\([^)]*\)\s+(\S.*?)(\s{2,}|$)", line)
            if m:
                out[m.group(1)] = m.group(2)
            continue
        m = re.match(r"^    ([a-z][a-z0-9_]*(?:, [a-z][a-z0-9_]*)*)\s+\([^)]*\)\s+"
                     r"(\S.*?)(\s{2,}|$)", line)
        if m and group:
            for name in m.group(1).split(", "):
                out[group.replace(" NAME>", "") + "/" + name] = m.group(2)
    return out


def check_docs_h5(text, datasets):
    for file, heading in (("results.h5", "## results.h5"), ("dynamic.h5", "### dynamic.h5")):
        start = text.index("\n" + heading + "\n")
        level = heading.split()[0]
        end = text.find("\n" + level + " ", start + 1)
        docs = doc_datasets(text[start:end if end > 0 else None])
        schema = {p: plain_units(u) for p, (u, _) in datasets[file].items()}
        if docs != schema:
            fail(f"docs/output.md, {file}: datasets (path: units) differ from the schema: "
                 f"not documented {sorted(set(schema.items()) - set(docs.items()))}, "
                 f"not in the schema {sorted(set(docs.items()) - set(schema.items()))}")
        print(f"docs/output.md: the {len(docs)} datasets of {file} as in the schema")


def doc_tables(text):
    """{file: [(column, unit)]} from docs/output.md: the first 'column | unit | meaning'
    table after each heading that names a .csv file; a cell naming several columns
    (`x_m`, `y_m`, `z_m`) gives each the unit of the row."""
    tables, lines = {}, text.splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"^#{2,4} `?([a-z_]+\.csv)`?\s*$", line)
        if not m:
            continue
        rows, j = [], i + 1
        while j < len(lines) and not lines[j].startswith("|"):
            if lines[j].startswith("#"):
                break
            j += 1
        if j == len(lines) or not lines[j].startswith("|"):
            tables[m.group(1)] = rows
            continue
        head = [c.strip() for c in lines[j].strip("|").split("|")]
        if head[:2] != ["column", "unit"]:
            fail(f"docs/output.md: the table under '{line}' is not 'column | unit | ...'")
        for row in lines[j + 2:]:
            if not row.startswith("|"):
                break
            cells = [c.strip() for c in row.strip("|").split("|")]
            for name in re.findall(r"`([^`]+)`", cells[0]):
                rows.append((name, cells[1]))
        tables[m.group(1)] = rows
    return tables


def check_docs(src, columns, headers, datasets):
    text = (src / "docs" / "output.md").read_text()
    check_docs_h5(text, datasets)
    docs = doc_tables(text)
    for file in docs:
        if file not in columns:
            fail(f"docs/output.md documents {file}, which the schema does not have")
    for file, cols in columns.items():
        if file == "environment.csv":
            if f"header `{headers[file]}`" not in text:
                fail(f"docs/output.md does not give environment.csv's header "
                     f"`{headers[file]}`")
            continue
        if file not in docs:
            fail(f"docs/output.md has no section (heading) for {file}")
        if docs[file] != cols:
            missing = [c for c in cols if c not in docs[file]]
            extra = [c for c in docs[file] if c not in cols]
            fail(f"docs/output.md, {file}: columns (name, unit) differ from the schema: "
                 f"not documented {missing}, not in the schema {extra}"
                 + ("" if missing or extra else " (order)"))
    print(f"docs/output.md: {len(columns)} tables, "
          f"{sum(len(c) for c in columns.values())} columns as in the schema")


def check_readers(src, columns, datasets):
    sys.path.insert(0, str(src / "postproc"))
    from rodyn_post import dynamic, environment, results, schema, sea
    py_columns = {f: [(c, u) for c, u, _ in cols] for f, cols in schema.COLUMNS.items()}
    if py_columns != columns or schema.DATASETS != datasets:
        fail("postproc/rodyn_post/schema.py differs from rodyn_output_schema: run "
             "python3 tools/gen_output_schema.py")
    print("rodyn_post.schema is rodyn_output_schema")
    used = {
        "static_nodes.csv": results.NODES_HEADER,
        "static_elements.csv": results.ELEMENTS_HEADER,
        "static_lines.csv": results.LINES_HEADER,
        "static_reactions.csv": results.REACTIONS_HEADER,
        "environment.csv": environment.ENVIRONMENT_HEADER,
        "dynamic_nodes.csv": dynamic.NODES_HEADER,
        "dynamic_elements.csv": dynamic.ELEMENTS_HEADER,
        "dynamic_lines.csv": dynamic.LINES_HEADER,
        "dynamic_ends.csv": dynamic.ENDS_HEADER,
        "dynamic_ends_step.csv": dynamic.ENDS_STEP_HEADER,
        "dynamic_log.csv": dynamic.LOG_HEADER,
    }
    for file in (sea.WAVES_CSV, sea.WAVES_STEP_CSV, sea.VESSELS_CSV, sea.VESSELS_STEP_CSV,
                 sea.CONNECTIONS_CSV, sea.CONNECTIONS_STEP_CSV):
        used[file] = schema.header(file)
    for file, names in used.items():
        schema = [c for c, _ in columns[file]]
        if any(n not in schema for n in names):
            fail(f"rodyn_post reads columns of {file} the schema does not have: "
                 f"{[n for n in names if n not in schema]}")
        if sorted(names, key=schema.index) != list(names):
            fail(f"rodyn_post's columns of {file} are not in the schema's order")
    print(f"rodyn_post: the columns it reads of {len(used)} tables are in the schema")


def check_run(src, work, rodyn, headers, datasets):
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    text = (src / "tests" / "program" / "mooring_waves.inp").read_text()
    inc = (src / "input" / "mooring_leg_section.inc").resolve()
    text = text.replace("INPUT=../../input/mooring_leg_section.inc", f"INPUT={inc}")
    text = text.replace("TIME=20.0, OUTPUT INTERVAL=0.5", "TIME=0.4, OUTPUT INTERVAL=0.2")
    text = text.replace("HDF5=NO", "HDF5=YES")
    # a wave probe and the fairlead on a vessel: the sea and vessel tables are written
    rao = (src / "input" / "fpso_rao.csv").resolve()
    text = text.replace("*SEABED,", "*CURRENT\n0, 0.5, 20\n-100, 0.1, 0\n*SEABED,")
    text = text.replace("*STATIC,", "*WAVE PROBE, NAME=P1\n0, 0\n"
                        f"*VESSEL, NAME=FPSO, TYPE=RAO, INPUT={rao}, PHASE=LEAD\n"
                        "0.0, 0.0, 0.0, 30.0\n"
                        "*MOTION, LINE=LEG, END=B, TYPE=VESSEL, VESSEL=FPSO, RAMP=0\n*STATIC,")
    # a clump weight (a FREE point) hung from a point of a FREE body on springs: the
    # points, the bodies, their periods and the stiffness
    springs = "".join(f"{', '.join('1e6' if i == j else '0' for j in range(6))}\n"
                      for i in range(6))
    text = text.replace("*STATIC,", "*BODY, NAME=PLAT, TYPE=FREE, MASS=1000\n-400, 50, -40\n"
                        "0, 0, 0\n0, 0, 0\n100, 100, 100\n"
                        f"*BODY HYDROSTATICS, BODY=PLAT\n{springs}"
                        "*POINT, NAME=PA, TYPE=BODY, BODY=PLAT\n0, 0, 0\n"
                        "*OFFSET CURVE, BODY=PLAT, FORCE=1e4, STEPS=2\n*MODAL, MODES=3\n"
                        "*POINT, NAME=PB, TYPE=FREE, MASS=500\n-400, 52, -69.9\n"
                        "*LINE, NAME=TETHER, SECTION=CHAIN, LENGTH=30.0, ELEMENTS=4, ORDER=3,"
                        " ELEMENT=CABLE, POINT A=PA, POINT B=PB\n*STATIC,")
    deck = work / "schema.inp"
    deck.write_text(text)
    out = work / "out"
    run = subprocess.run([rodyn, str(deck), "-o", str(out), "--quiet"], capture_output=True,
                         text=True, timeout=300)
    if run.returncode != 0:
        fail(f"rodyn {deck}: exit {run.returncode}: {run.stderr}")
    for file, header in headers.items():
        path = out / file
        if not path.is_file():
            fail(f"{path}: not written")
        first = path.read_text().split("\n", 1)[0]
        if first != header:
            fail(f"{path}: header {first!r}, the schema's {header!r}")
    print(f"a run writes the {len(headers)} tables with the schema's headers")
    try:
        import h5py
    except ImportError:
        print("h5py missing: the HDF5 attributes are not checked")
        return
    for name in ("results.h5", "dynamic.h5"):
        bare, found = [], {}

        def visit(path, obj):
            if isinstance(obj, h5py.Dataset):
                if not {"units", "description"} <= set(obj.attrs):
                    bare.append(path)
                    return
                key = re.sub(r"^(static|dynamic|modes)/(LEG|TETHER)/", r"\1/LINE/", path)
                found["/" + key] = (str(obj.attrs["units"]), str(obj.attrs["description"]))
        with h5py.File(out / name, "r") as f:
            f.visititems(visit)
        if bare:
            fail(f"{out / name}: datasets without units and description: {bare}")
        found_schema = {k: v for k, v in found.items() if not k.startswith("/environment/")}
        if found_schema != datasets[name]:
            other = [k for k in found_schema
                     if k in datasets[name] and found_schema[k] != datasets[name][k]]
            fail(f"{out / name}: datasets (path: units, description) differ from the "
                 f"schema: not written {set(datasets[name]) - set(found_schema)}, not in the "
                 f"schema {set(found_schema) - set(datasets[name])}, other attributes {other}")
        print(f"{name}: all {len(found)} datasets carry units and description, "
              f"those of the schema its own")


def main():
    dump, src, work, rodyn = sys.argv[1:5]
    src, work = pathlib.Path(src).resolve(), pathlib.Path(work).resolve()
    columns, headers, datasets, status, environment, attributes = read_schema(dump)
    for file, cols in columns.items():
        if headers.get(file) != ",".join(c for c, _ in cols):
            fail(f"{file}: the header {headers.get(file)!r} is not the schema's columns")
    check_docs(src, columns, headers, datasets)
    check_readers(src, columns, datasets)
    check_run(src, work, rodyn, headers, datasets)
    check_status(src, status, work / "out")
    check_environment(src, environment, work / "out")
    check_attributes(src, attributes, work / "out")
    check_docs_attributes(src, attributes)
    print("OK")


if __name__ == "__main__":
    main()
