#!/usr/bin/env python3
"""Attribute bytes of gab beside Google Draco's, per file and per attribute kind.

Run (from the repository root, after building build/apps/gab; Debian packages
draco and assimp-testmodels, /usr/bin/python3 with numpy for --shared):

    python3 bench/attribute_compare.py                  # assimp's four files
    python3 bench/attribute_compare.py --shared         # + the shared meshes with normals, 8 and 10 bits
    python3 bench/attribute_compare.py --files a.obj b.ply

What it measures:

* Draco (`draco_encoder -cl 10`, its default quantization: positions 11 bits,
  normals 8, texture coordinates 10, generic 8): attribute bytes are its file
  minus the same file with every attribute skipped (`--skip NORMAL --skip
  TEX_COORD --skip COLOR --skip GENERIC`), and per kind the file minus the file
  with that kind skipped.
* gab (`gab compress --json`, its defaults: normals 8 bits, texture
  coordinates 10, colours 8, generic 16 (integer-typed values exactly)): the
  attribute sections' bytes from the JSON, in total and per attribute, with
  the largest error of each (degrees for normals; value units otherwise).
  gab's attribute bytes do not depend on the geometry's error target: the
  attributes are predicted from the connectivity alone.
* --shared: every mesh of ../shared/meshes given area-weighted vertex normals
  (written as binary PLY, float), coded at normal bits 8 and 10 by both
  (Draco -qn 8 / -qn 10).

Prints a markdown table and the sums. Runs one process at a time.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
ASSIMP = "/usr/share/assimp/models"
DEFAULT_FILES = [ASSIMP + "/OBJ/spider.obj", ASSIMP + "/OBJ/WusonOBJ.obj", ASSIMP + "/OBJ/regr01.obj",
                 ASSIMP + "/PLY/Wuson.ply"]
# What draco_encoder --skip takes (colours cannot be skipped: a file with them counts them with the positions).
KINDS = {"NORMAL": "normals", "TEX_COORD": "texture_coordinates", "GENERIC": "generic"}


def draco_size(path, out, extra):
    subprocess.run(["draco_encoder", "-i", path, "-o", out, "-cl", "10"] + extra, check=True,
                   capture_output=True)
    return os.path.getsize(out)


def draco_attributes(path, tmp, qn=None):
    """Draco's attribute bytes in total and per kind (those present)."""
    extra = ["-qn", str(qn)] if qn else []
    out = os.path.join(tmp, "d.drc")
    full = draco_size(path, out, extra)
    skip_all = []
    for k in KINDS:
        skip_all += ["--skip", k]
    bare = draco_size(path, out, extra + skip_all)
    kinds = {}
    for k, label in KINDS.items():
        without = draco_size(path, out, extra + ["--skip", k])
        if without != full:
            kinds[label] = full - without
    return full, full - bare, kinds


def gab_attributes(gab, path, tmp, normal_bits=None):
    out = os.path.join(tmp, "g.gab")
    cmd = [gab, "compress", "-i", path, "-o", out, "--json", "--quiet"]
    if normal_bits:
        cmd += ["--normal-bits", str(normal_bits)]
    r = subprocess.run(cmd, check=True, capture_output=True, text=True)
    j = json.loads(r.stdout)
    per = {}
    for a in j.get("attributes", []):
        label = a["label"].split(":")[0]
        per[label] = per.get(label, 0) + a["bytes"]
    errors = {a["label"]: a["max_error"] for a in j.get("attributes", [])}
    return j["bytes"], j.get("attribute_bytes", 0), per, errors


def write_normals_ply(off_path, out_path):
    import numpy as np
    with open(off_path) as f:
        toks = f.read().split()
    nv, nf = int(toks[1]), int(toks[2])
    v = np.array(toks[4:4 + 3 * nv], float).reshape(nv, 3)
    faces = np.array(toks[4 + 3 * nv:4 + 3 * nv + 4 * nf], int).reshape(nf, 4)[:, 1:]
    n = np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])
    normals = np.zeros_like(v)
    for k in range(3):
        np.add.at(normals, faces[:, k], n)
    length = np.linalg.norm(normals, axis=1)
    length[length == 0] = 1
    normals /= length[:, None]
    with open(out_path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                 "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                 "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (nv, nf)).encode())
        f.write(np.hstack([v, normals]).astype("<f4").tobytes())
        rec = np.zeros(nf, dtype=[("n", "u1"), ("i", "<i4", 3)])
        rec["n"] = 3
        rec["i"] = faces
        f.write(rec.tobytes())


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--gab", default=os.path.join(ROOT, "build", "apps", "gab"))
    p.add_argument("--files", nargs="*", default=None)
    p.add_argument("--shared", action="store_true")
    a = p.parse_args()
    if shutil.which("draco_encoder") is None:
        print("draco_encoder not installed (apt-get install draco): nothing to compare")
        return 0
    files = a.files if a.files is not None else [f for f in DEFAULT_FILES if os.path.exists(f)]
    if a.files is None and not files:
        print("assimp-testmodels not installed (apt-get install assimp-testmodels)")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        jobs = [(f, None) for f in files]
        if a.shared:
            for name in sorted(os.listdir(os.path.join(ROOT, "..", "shared", "meshes"))):
                if not name.endswith(".off"):
                    continue
                ply = os.path.join(tmp, name[:-4] + ".normals.ply")
                write_normals_ply(os.path.join(ROOT, "..", "shared", "meshes", name), ply)
                jobs += [(ply, 8), (ply, 10)]
        for path, bits in jobs:
            d_full, d_attr, d_kinds = draco_attributes(path, tmp, bits)
            g_full, g_attr, g_kinds, g_err = gab_attributes(a.gab, path, tmp, bits)
            rows.append((os.path.basename(path), bits, d_full, d_attr, d_kinds, g_full, g_attr, g_kinds, g_err))
    print("| file | normal bits | Draco file | Draco attributes | gab file | gab attributes | gab / Draco "
          "(attributes) | per kind, gab / Draco bytes | gab's largest errors |")
    print("|---|---:|---:|---:|---:|---:|---:|---|---|")
    sums = {}
    for name, bits, d_full, d_attr, d_kinds, g_full, g_attr, g_kinds, g_err in rows:
        kinds = ", ".join("%s %d / %d" % (k, g_kinds.get(k, 0), d_kinds.get(k, 0))
                          for k in sorted(set(d_kinds) | set(g_kinds)))
        errs = ", ".join("%s %.3g" % (k, v) for k, v in g_err.items())
        ratio = g_attr / d_attr if d_attr else float("nan")
        print("| %s | %s | %d | %d | %d | %d | %.3f | %s | %s |" % (name, bits or "default", d_full, d_attr, g_full,
                                                                   g_attr, ratio, kinds, errs))
        # Summed over what both carry: the kinds Draco keeps (it drops PLY's s t, gab OBJ's materials).
        key = "assimp" if bits is None else "shared, %d bits" % bits
        s = sums.setdefault(key, [0, 0, {}, {}])
        for k, v in d_kinds.items():
            if k not in g_kinds:
                continue
            s[0] += v
            s[1] += g_kinds[k]
            s[2][k] = s[2].get(k, 0) + v
            s[3][k] = s[3].get(k, 0) + g_kinds[k]
    print()
    for key, (d, g, dk, gk) in sums.items():
        kinds = ", ".join("%s %d / %d = %.3f" % (k, gk[k], dk[k], gk[k] / dk[k]) for k in sorted(dk) if dk[k])
        print("%s, the kinds both carry: gab %d / Draco %d attribute bytes = %.3f (%s)" %
              (key, g, d, g / d if d else 0, kinds))
    return 0


if __name__ == "__main__":
    sys.exit(main())
