#!/usr/bin/python3
"""Writes the seeds of the `ibms compare` fuzzer (compare_seeds/, format: fuzz_compare_input.hpp):
each case's shipped ibms reference CSVs (validation/<case>/reference/ibms_*.csv), thinned to at
most about 8 kB per file by keeping every k-th data row (comment and header lines kept), given as
the submitted file; the published tables; and the bad inputs of the compare tests
(verification/app/test_compare*.sh): a non-number, a ragged row, a missing column, a repeated time,
one row, a missing profile. Run from anywhere: python3 make_compare_seeds.py"""
import os

here = os.path.dirname(os.path.abspath(__file__))
validation = os.path.join(here, "..", "..", "validation")
out = os.path.join(here, "compare_seeds")
LIMIT = 8000


def lines_of(case, name):
    with open(os.path.join(validation, case, "reference", name)) as f:
        return f.read().splitlines()


def thin(lines):
    """Comment lines, the header and every k-th data row, so that the text stays near LIMIT bytes."""
    head = [l for l in lines if l.startswith("#") or not l.strip()]
    rest = [l for l in lines if not (l.startswith("#") or not l.strip())]
    header, rows = rest[0], rest[1:]
    size = sum(len(l) + 1 for l in rows)
    k = max(1, -(-size // LIMIT))
    return head + [header] + rows[::k]


def write(name, case, files):
    text = "#case " + case + "\n" + "#file\n".join("\n".join(f) + "\n" for f in files)
    with open(os.path.join(out, name), "w") as f:
        f.write(text)


def data_row(lines, n):
    """Index of the n-th data row (0-based) after the header."""
    seen = -1
    for i, l in enumerate(lines):
        if l.startswith("#") or not l.strip():
            continue
        if seen >= n:
            return i
        seen += 1
    return len(lines) - 1


os.makedirs(out, exist_ok=True)
for f in os.listdir(out):
    os.remove(os.path.join(out, f))
cavities = {"lid_driven_cavity_re100": "ghia_u_re100.csv", "lid_driven_cavity_re400": "ghia_u_re400.csv",
            "lid_driven_cavity_re1000": "ghia_u_re1000.csv", "two_sided_cavity_re100": None}
for case, ghia in cavities.items():
    u, v = lines_of(case, "ibms_centreline_u.csv"), lines_of(case, "ibms_centreline_v.csv")
    write(case + "_ibms.csv", case, [u, v])
    if ghia:
        write(case + "_ghia_u_only.csv", case, [lines_of(case, ghia)])  # no v profile: refused
u, v = lines_of("lid_driven_cavity_re100", "ibms_centreline_u.csv"), lines_of("lid_driven_cavity_re100", "ibms_centreline_v.csv")
bad = list(u); i = data_row(bad, 8); bad[i] = bad[i].split(",")[0] + ",abc"
write("cavity_bad_number.csv", "lid_driven_cavity_re100", [bad, v])
ragged = list(u); i = data_row(ragged, 10); ragged[i] += ",7"
write("cavity_ragged.csv", "lid_driven_cavity_re100", [ragged, v])
write("unknown_case.csv", "no_such_case", [u])

settling = thin(lines_of("settling_disk", "ibms_settling_history.csv"))
write("settling_disk_ibms.csv", "settling_disk", [settling])
write("settling_disk_published.csv", "settling_disk", [lines_of("settling_disk", "settling_disk_rho1.25.csv")])
write("settling_disk_two_files.csv", "settling_disk", [settling, settling])

dkt = ["t [s],y_trailing [cm],y_leading [cm],v_trailing [cm/s],v_leading [cm/s]"]
import math
for k in range(0, 301, 3):
    t = k / 100
    vt = -1.69 * math.exp(-((t - 1.12) / 0.5) ** 2)
    dkt.append("%.2f,%.6f,%.6f,%.6f,%.6f" % (t, 7.2 - 1.1 * t, 6.8 - 0.8 * t, vt, 0.9 * vt))
write("dkt_synthetic.csv", "dkt_two_disks", [dkt])
write("dkt_missing_column.csv", "dkt_two_disks", [[l.rsplit(",", 2)[0] for l in dkt]])
write("dkt_published.csv", "dkt_two_disks", [lines_of("dkt_two_disks", "wan_turek_dkt_positions_digitized.csv")])

plain = thin(lines_of("cavity_swelling_particles", "ibms_trajectories_nonswelling.csv"))
swell = thin(lines_of("cavity_swelling_particles", "ibms_trajectories_swelling.csv"))
write("swelling_particles_ibms.csv", "cavity_swelling_particles", [plain, swell])
write("swelling_particles_one_file.csv", "cavity_swelling_particles", [plain])
repeated = list(plain); i = data_row(repeated, 20); repeated.insert(i, repeated[i])
write("swelling_particles_repeated_time.csv", "cavity_swelling_particles", [repeated, swell])
k10 = thin(lines_of("cavity_deformable_objects", "ibms_deformation_k10.csv"))
k100 = thin(lines_of("cavity_deformable_objects", "ibms_deformation_k100.csv"))
write("deformable_ibms.csv", "cavity_deformable_objects", [k10, k100])
bad_id = list(k10); i = data_row(bad_id, 12); cells = bad_id[i].split(","); cells[1] = "x"; bad_id[i] = ",".join(cells)
write("deformable_bad_id.csv", "cavity_deformable_objects", [bad_id, k100])

write("dfg_2d1_ibms.csv", "dfg_cylinder_2d1", [lines_of("dfg_cylinder_2d1", "ibms_dfg_2d1.csv")])
write("dfg_2d1_published.csv", "dfg_cylinder_2d1", [lines_of("dfg_cylinder_2d1", "dfg_2d1.csv")])
write("dfg_2d1_bad.csv", "dfg_cylinder_2d1", [["c_d", "abc"]])
write("dfg_2d1_no_drag.csv", "dfg_cylinder_2d1", [["c_l", "0.01"]])
write("dfg_2d2_ibms.csv", "dfg_cylinder_2d2", [thin(lines_of("dfg_cylinder_2d2", "ibms_dfg_2d2_forces.csv"))])
write("dfg_2d2_published.csv", "dfg_cylinder_2d2", [lines_of("dfg_cylinder_2d2", "dfg_2d2.csv")])
write("dfg_2d2_short.csv", "dfg_cylinder_2d2", [["time,drag_coefficient,lift_coefficient", "0,3,0", "1,3,1"]])
print("wrote", len(os.listdir(out)), "seeds to", out)
