#!/usr/bin/env python3
"""Sphere count against error for the shared characters and the mannequin.

Runs `proxygi fit MODEL --json --force -o TMP --tolerance T` over a range of tolerances and plots
the number of spheres against (left) the one-sided Hausdorff distance from the spheres' union
boundary to the mesh surface and (right) the outside-volume ratio, both as measured by
proxies/quality.h. Distances are relative to each character's bind-pose bounding-box diagonal.

usage: scripts/proxies_chart.py PROXYGI_BINARY SHARED_GLTF_DIR OUT.png [OUT.json]
"""
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TOLERANCES = [0.02, 0.03, 0.04, 0.05, 0.07, 0.10]


def main():
    binary, gltf_dir, out_png = sys.argv[1], sys.argv[2], sys.argv[3]
    out_json = sys.argv[4] if len(sys.argv) > 4 else None
    models = [(name, os.path.join(gltf_dir, name + ".glb")) for name in ("CesiumMan", "Fox", "RiggedSimple")]
    models = [(n, p) for n, p in models if os.path.exists(p)] + [("mannequin", "mannequin")]
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, path in models:
            rows = []
            for t in TOLERANCES:
                rig = os.path.join(tmp, f"{name}-{t}.proxies.json")
                out = subprocess.run([binary, "fit", path, "--json", "--force", "-o", rig, "--tolerance", str(t)],
                                     check=True, capture_output=True, text=True).stdout
                r = json.loads(out)
                rows.append({"tolerance": t, "spheres": r["sphere_count"],
                             "hausdorff_rel": r["hausdorff_spheres_to_surface_m"] / r["diagonal_m"],
                             "outside_volume_ratio": r["outside_volume_ratio"], "coverage": r["coverage"],
                             "fit_seconds": r["fit_seconds"], "binding": r["binding"],
                             "rigid_worst_rel": r["tracking"]["rigid_worst_poke_out_m"] / r["diagonal_m"],
                             "blended_worst_rel": r["tracking"]["blended_worst_poke_out_m"] / r["diagonal_m"]})
                print(name, rows[-1], flush=True)
            results[name] = rows
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, rows in results.items():
        n = [r["spheres"] for r in rows]
        a.plot(n, [100 * r["hausdorff_rel"] for r in rows], "o-", label=name)
        b.plot(n, [100 * r["outside_volume_ratio"] for r in rows], "o-", label=name)
    a.set_xlabel("spheres")
    a.set_ylabel("Hausdorff spheres→surface (% of diagonal)")
    a.set_title("protrusion vs sphere count (tolerances 2–10 %)")
    b.set_xlabel("spheres")
    b.set_ylabel("outside volume (% of union volume)")
    b.set_title("outside volume vs sphere count")
    for ax in (a, b):
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    if out_json:
        with open(out_json, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
