#!/usr/bin/env bash
# Study (not a test): the stability matrix of doc/stability.md. Runs the
# executable on stiff and extreme cases -- penalty c from 1e-8 to 10,
# relaxation below and above gamma*, nu -> 1/2 (Q1, Q1 with reduced
# volumetric integration, Q2), material contrast 1e-4..1e4, slender bodies, no contact / zero gap /
# initial penetration / tiny and large approach, one-cell and fine meshes,
# SI against MPa/cm -- and checks every answer against something
# independent:
#   closed   the closed form of prm/stability/uniaxial.prm,
#            p = (Delta - g0)^+ / ((1-nu_1^2) H1/E_1 + (1-nu_2^2) H2/E_2 + theta),
#            read back from the run's own parameters.prm and theta;
#   CASE     another run (the monolithic Newton solver on the same meshes,
#            a fine degree-2 reference, or the same scene in other units,
#            scaled);
#   report   the case must stop with exit code 4 (or 1) and a message that
#            names the parameter to change.
# Every case must converge to the right answer or stop with such a message:
# a hang (timeout), a crash, a NaN or a silently wrong answer is a FAIL.
#
# usage: scripts/stability_matrix.sh [EXECUTABLE]   (default build/ddcontact)
#   STABILITY_HUGE=1 adds the ~1e6 unknowns-per-body case (minutes, ~4 GB).
# Writes doc/stability.csv, prints the table and writes it into the tables
# of doc/stability.md (scripts/stability_tables.py), whose text discusses it.
set -uo pipefail
cd "$(dirname "$0")/.."
exe=$(realpath "${1:-build/ddcontact}")
[ -x "$exe" ] || { echo "no executable $exe" >&2; exit 1; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
manifest="$work/manifest"
: >"$manifest"

paper=prm/paper_two_bodies.prm
uni=prm/stability/uniaxial.prm
# The paper's scene on fixed meshes (16 x 4 quads below, 64 x 16 x 2
# triangles above), converged far below the discretisation error.
P=(--set "Adaptation/Mode=none" --set "Output/Write vtu=false"
  --set "Contact solver/Domain decomposition/Relaxation=anderson"
  --set "Contact solver/Tolerance=1e-10")
MONO=(--set "Contact solver/Solver=monolithic")

# run NAME GROUP REFERENCE TOLERANCE "DESCRIPTION" SCENE [--set ...]
run() {
  local name=$1 group=$2 ref=$3 tol=$4 desc=$5 scene=$6
  shift 6
  local dir="$work/$name" limit=${TIMEOUT:-600}
  mkdir -p "$dir"
  timeout "$limit" "$exe" --output "$dir/out" "$@" "$scene" \
    </dev/null >"$dir/stdout" 2>"$dir/stderr"
  local code=$?
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$group" "$ref" "$tol" "$desc" "$code" >>"$manifest"
  printf '  %-24s exit %3d  %s\n' "$name" "$code" "$(head -c 160 "$dir/stderr")" >&2
}

echo "running the stability matrix with $exe" >&2

# --- penalty: theta = c H / E_1; the closed form contains theta, so every c
#     has an exact answer; the monolithic matrix K + C^T C / theta has a
#     condition number growing like 1/c.
for c in 1e-8 1e-6 1e-4 1e-2 0.05 1 10; do
  run "pen_c${c}_anderson" penalty closed 1e-6 "uniaxial, c=$c, anderson" $uni \
    --set "Contact pair S/Penalty=$c"
  run "pen_c${c}_mono" penalty closed 1e-6 "uniaxial, c=$c, monolithic" $uni \
    --set "Contact pair S/Penalty=$c" "${MONO[@]}"
done
for c in 1e-4 0.05 10; do
  run "pen_c${c}_fixed0.02" penalty closed 1e-6 "uniaxial, c=$c, fixed gamma=0.02" $uni \
    --set "Contact pair S/Penalty=$c" --set "Contact solver/Domain decomposition/Relaxation=fixed" \
    --set "Contact solver/Domain decomposition/Gamma=0.02" --set "Contact solver/Max iterations=20000"
done
for c in 1e-8 1e-6 1e-4 0.05 10; do
  run "paper_c${c}_mono" penalty - - "paper scene, c=$c, monolithic" $paper "${P[@]}" \
    --set "Contact pair S/Penalty=$c" "${MONO[@]}"
  run "paper_c${c}_anderson" penalty "paper_c${c}_mono" 1e-6 "paper scene, c=$c, anderson" $paper \
    "${P[@]}" --set "Contact pair S/Penalty=$c"
done

# --- relaxation on the paper's scene (gamma* ~ 0.056 estimated), against
#     the monolithic solver; Tolerance 1e-8 for the slow fixed runs.
run paper_mono relaxation - - "paper scene, monolithic reference" $paper "${P[@]}" "${MONO[@]}"
for g in 1e-3 1e-2 0.03 0.05 0.06 0.1 0.5 1; do
  ref=paper_mono; tol=1e-5
  case $g in 0.1|0.5|1) ref=report; tol=- ;; esac
  run "relax_fixed${g}" relaxation "$ref" "$tol" "paper scene, fixed gamma=$g" $paper "${P[@]}" \
    --set "Contact solver/Domain decomposition/Relaxation=fixed" --set "Contact solver/Domain decomposition/Gamma=$g" \
    --set "Contact solver/Tolerance=1e-8" --set "Contact solver/Max iterations=50000"
done
for r in auto aitken anderson; do
  run "relax_${r}" relaxation paper_mono 1e-6 "paper scene, $r" $paper "${P[@]}" \
    --set "Contact solver/Domain decomposition/Relaxation=$r"
done
run relax_anderson_c1e-8 relaxation paper_c1e-8_mono 1e-5 "paper scene, c=1e-8, anderson depth 30" $paper "${P[@]}" \
  --set "Contact pair S/Penalty=1e-8" --set "Contact solver/Domain decomposition/Anderson depth=30"
run relax_eps1e-16 relaxation report - "paper scene, Tolerance=1e-16 (below round-off)" $paper "${P[@]}" \
  --set "Contact solver/Tolerance=1e-16"

# --- near-incompressible: the paper's scene with both bodies of
#     quadrilaterals (Q1, Q1 with selective reduced integration of the
#     volumetric term, Q2) at refinement 1, against Q2 at refinement 3.
Q=(--set "Body omega1/Element/Cell type=quadrilateral" --set "Body omega1/Mesh/Initial refinement=1"
  --set "Body omega2/Mesh/Initial refinement=1")
for nu in 0.3 0.45 0.49 0.499 0.4999; do
  NU=(--set "Body omega1/Material/Poisson's ratio=$nu" --set "Body omega2/Material/Poisson's ratio=$nu")
  run "nu${nu}_ref_q2" incompressible - - "nu=$nu, Q2 refinement 3 (reference)" $paper "${P[@]}" "${NU[@]}" \
    --set "Body omega1/Element/Cell type=quadrilateral" \
    --set "Body omega1/Mesh/Initial refinement=3" --set "Body omega2/Mesh/Initial refinement=3" \
    --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2"
  q1ref="nu${nu}_ref_q2"; q1tol=0.05
  case $nu in 0.499|0.4999) q1ref=report; q1tol=- ;; esac # refused: locks
  run "nu${nu}_q1" incompressible "$q1ref" "$q1tol" "nu=$nu, Q1 refinement 1" $paper "${P[@]}" "${NU[@]}" "${Q[@]}"
  run "nu${nu}_q1_reduced" incompressible "nu${nu}_ref_q2" 0.05 "nu=$nu, Q1 reduced volumetric, refinement 1" \
    $paper "${P[@]}" "${NU[@]}" "${Q[@]}" \
    --set "Body omega1/Element/Volumetric integration=reduced" \
    --set "Body omega2/Element/Volumetric integration=reduced"
  run "nu${nu}_q2" incompressible "nu${nu}_ref_q2" 0.05 "nu=$nu, Q2 refinement 1" $paper "${P[@]}" "${NU[@]}" "${Q[@]}" \
    --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2"
done
run nu0.4999_uniaxial_reduced incompressible closed 1e-6 "uniaxial, nu=0.4999, Q1 reduced (patch test)" $uni \
  --set "Body omega1/Element/Cell type=quadrilateral" \
  --set "Body omega1/Element/Volumetric integration=reduced" --set "Body omega2/Element/Volumetric integration=reduced" \
  --set "Body omega1/Material/Poisson's ratio=0.4999" --set "Body omega2/Material/Poisson's ratio=0.4999"
run nu0.4999_uniaxial_p2q2 incompressible closed 1e-6 "uniaxial, nu=0.4999, P2 above, Q2 below" $uni \
  --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2" \
  --set "Body omega1/Material/Poisson's ratio=0.4999" --set "Body omega2/Material/Poisson's ratio=0.4999"

# --- material contrast E_1/E_2 (E_2 = 2.1e5) and slender bodies.
for r in 1e-4 1e-2 1 1e2 1e4; do
  E1=$(python3 -c "print(2.1e5*$r)")
  run "contrast_${r}" contrast closed 1e-6 "uniaxial, E1/E2=$r, anderson" $uni \
    --set "Body omega1/Material/Young's modulus=$E1"
  run "contrast_${r}_paper_mono" contrast - - "paper scene, E1/E2=$r, monolithic" $paper "${P[@]}" "${MONO[@]}" \
    --set "Body omega1/Material/Young's modulus=$E1"
  run "contrast_${r}_paper" contrast "contrast_${r}_paper_mono" 1e-6 "paper scene, E1/E2=$r, anderson" $paper "${P[@]}" \
    --set "Body omega1/Material/Young's modulus=$E1"
done
# E_1/E_2 = 1e4 with the soft body as Body 1 (as the message proposes):
# theta = c H/E_1 is then relative to the compliant side.
run contrast_1e4_swapped contrast closed 1e-6 "uniaxial, E1/E2=1e-4 written as Body 1 = soft (the E1/E2=1e4 scene swapped)" $uni \
  --set "Body omega2/Material/Young's modulus=2.1e9"
run slender_uniaxial contrast closed 1e-6 "uniaxial, H/L=0.01 (4 x 0.04 each, 100 x 1 cells)" $uni \
  --set "Body omega1/Mesh/Corner 1=0, 0.04" --set "Body omega1/Mesh/Corner 2=4, 0.08" \
  --set "Body omega1/Mesh/Subdivisions=100, 1" --set "Body omega2/Mesh/Corner 2=4, 0.04" \
  --set "Body omega2/Mesh/Subdivisions=75, 1" --set "Constants=Delta=1e-5, g0=0" \
  --set "Output/Points=omega2: 1, 0.02"
# A plate of H/L = 0.01 clamped at both ends, pressed by a pressure onto a
# block across the gap r0 x1^2: its bending compliance is ~1e7 times theta.
S=(--set "Body omega1/Mesh/Corner 1=-2, 1" --set "Body omega1/Mesh/Corner 2=2, 1.04"
  --set "Body omega1/Mesh/Subdivisions=100, 1" --set "Body omega1/Mesh/Initial refinement=1"
  --set "Body omega1/Element/Cell type=quadrilateral" --set "Body omega1/Element/Degree=2"
  --set "Body omega1/Boundary conditions/Dirichlet=0: xy: 0; 0 | 1: xy: 0; 0"
  --set "Body omega1/Boundary conditions/Neumann=3: 0; -q" --set "Constants=r0=1e-3, q=0.01")
run slender_plate_mono contrast - - "plate H/L=0.01 clamped at its ends, pressure q, monolithic" $paper "${P[@]}" "${S[@]}" "${MONO[@]}"
run slender_plate contrast slender_plate_mono 1e-5 "plate H/L=0.01, anderson" $paper "${P[@]}" "${S[@]}"
for c in 1 100 1e5; do
  run "slender_plate_c${c}_mono" contrast - - "plate H/L=0.01, c=$c, monolithic" $paper "${P[@]}" "${S[@]}" "${MONO[@]}" \
    --set "Contact pair S/Penalty=$c"
  run "slender_plate_c${c}" contrast "slender_plate_c${c}_mono" 1e-5 "plate H/L=0.01, c=$c, anderson" $paper "${P[@]}" "${S[@]}" \
    --set "Contact pair S/Penalty=$c"
done
# The divergence message of slender_plate_c1e5 proposes fixed gamma = 0.084.
run slender_plate_c1e5_fixed contrast slender_plate_c1e5_mono 1e-5 "plate H/L=0.01, c=1e5, fixed gamma=0.084 (as the message proposes)" \
  $paper "${P[@]}" "${S[@]}" --set "Contact pair S/Penalty=1e5" \
  --set "Contact solver/Domain decomposition/Relaxation=fixed" --set "Contact solver/Domain decomposition/Gamma=0.084"
run slender_plate_fixed contrast report - "plate H/L=0.01, fixed gamma=0.02" $paper "${P[@]}" "${S[@]}" \
  --set "Contact solver/Domain decomposition/Relaxation=fixed"

# --- contact extremes.
run uni_no_contact contact closed 1e-12 "uniaxial, g0=2e-3 > Delta: no contact" $uni --set "Constants=Delta=1.366e-3, g0=2e-3"
run uni_zero_gap contact closed 1e-6 "uniaxial, g0=0: contact along the whole zone" $uni
run uni_penetration contact closed 1e-6 "uniaxial, Delta=0, g0=-1e-3: initial penetration" $uni --set "Constants=Delta=0, g0=-1e-3"
run uni_tiny contact closed 1e-6 "uniaxial, Delta=1e-12 cm" $uni --set "Constants=Delta=1e-12, g0=0"
run uni_large contact closed 1e-6 "uniaxial, Delta=0.05 cm (2.5 % strain)" $uni --set "Constants=Delta=0.05, g0=0"
run uni_pull contact closed 1e-12 "uniaxial, Delta=-1e-3: bodies pulled apart" $uni --set "Constants=Delta=-1e-3, g0=0"
for k in no_contact:"r0=1e-3, Delta=0" zero_gap:"r0=0, Delta=1.366e-3" tiny:"r0=1e-3, Delta=1e-12" \
  large:"r0=1e-3, Delta=0.05"; do
  n=${k%%:*}; consts=${k#*:}
  run "paper_${n}_mono" contact - - "paper scene, $consts, monolithic" $paper "${P[@]}" "${MONO[@]}" --set "Constants=$consts"
  run "paper_${n}" contact "paper_${n}_mono" 1e-6 "paper scene, $consts, anderson" $paper "${P[@]}" --set "Constants=$consts"
done
run paper_penetration_mono contact - - "paper scene, gap r0 x^2 - 1e-3, Delta=0, monolithic" $paper "${P[@]}" "${MONO[@]}" \
  --set "Constants=r0=1e-3, Delta=0" --set "Contact pair S/Gap=r0*x^2 - 1e-3"
run paper_penetration contact paper_penetration_mono 1e-6 "paper scene, gap r0 x^2 - 1e-3, Delta=0, anderson" $paper "${P[@]}" \
  --set "Constants=r0=1e-3, Delta=0" --set "Contact pair S/Gap=r0*x^2 - 1e-3"

# --- meshes: one cell across, and fine.
run uni_one_cell mesh closed 1e-8 "uniaxial, one cell per body" $uni \
  --set "Body omega1/Mesh/Subdivisions=1, 1" --set "Body omega2/Mesh/Subdivisions=1, 1"
run paper_one_cell_mono mesh - - "paper scene, one cell per body, monolithic" $paper "${P[@]}" "${MONO[@]}" \
  --set "Body omega1/Mesh/Subdivisions=1, 1" --set "Body omega1/Mesh/Initial refinement=0" \
  --set "Body omega2/Mesh/Subdivisions=1, 1"
run paper_one_cell mesh paper_one_cell_mono 1e-6 "paper scene, one cell per body, anderson" $paper "${P[@]}" \
  --set "Body omega1/Mesh/Subdivisions=1, 1" --set "Body omega1/Mesh/Initial refinement=0" \
  --set "Body omega2/Mesh/Subdivisions=1, 1"
run uni_fine_2e5 mesh closed 1e-6 "uniaxial, 640 x 160 cells per body (2.1e5 dofs each)" $uni \
  --set "Body omega1/Mesh/Subdivisions=40, 10" --set "Body omega1/Mesh/Initial refinement=4" \
  --set "Body omega2/Mesh/Subdivisions=40, 10" --set "Body omega2/Mesh/Initial refinement=4"
run paper_fine_2e5_mono mesh - - "paper scene, 512 x 128 quads, 2 x 512 x 128 triangles, monolithic" $paper "${P[@]}" "${MONO[@]}" \
  --set "Body omega1/Mesh/Initial refinement=5" --set "Body omega2/Mesh/Initial refinement=5"
run paper_fine_2e5 mesh paper_fine_2e5_mono 1e-6 "paper scene, 512 x 128 quads (1.3e5 dofs each), anderson" $paper "${P[@]}" \
  --set "Body omega1/Mesh/Initial refinement=5" --set "Body omega2/Mesh/Initial refinement=5"
if [ "${STABILITY_HUGE:-0}" = 1 ]; then
  run uni_fine_1e6 mesh closed 1e-6 "uniaxial, 1440 x 360 cells per body (1.04e6 dofs each), cg-amg" $uni \
    --set "Body omega1/Element/Cell type=quadrilateral" \
    --set "Body omega1/Mesh/Subdivisions=1440, 360" --set "Body omega2/Mesh/Subdivisions=1440, 360" \
    --set "Body omega1/Solver/Type=cg-amg" --set "Body omega2/Solver/Type=cg-amg" \
    --set "Contact solver/Tolerance=1e-8"
fi

# --- units: the same scenes in m and Pa; u scales by 1e-2, the force per
#     unit thickness by 1e6 * 1e-2 = 1e4 (MPa cm -> N/m).
SI=(--set "Body omega1/Material/Young's modulus=2.1e11" --set "Body omega2/Material/Young's modulus=2.1e11")
run units_uni_si units closed 1e-6 "uniaxial in m, Pa" $uni "${SI[@]}" \
  --set "Body omega1/Mesh/Corner 1=0, 0.01" --set "Body omega1/Mesh/Corner 2=0.04, 0.02" \
  --set "Body omega2/Mesh/Corner 2=0.04, 0.01" --set "Constants=Delta=1.366e-5, g0=0" \
  --set "Output/Points=omega2: 0.01, 0.005"
SIP=("${SI[@]}" --set "Body omega1/Mesh/Corner 1=-0.02, 0.01" --set "Body omega1/Mesh/Corner 2=0.02, 0.02"
  --set "Body omega2/Mesh/Corner 1=-0.02, 0" --set "Body omega2/Mesh/Corner 2=0.02, 0.01"
  --set "Constants=r0=0.1, Delta=1.366e-5" --set "Output/Points=omega2: 0.005, 0.0075")
run units_paper_cm units paper_mono 1e-6 "paper scene in cm, MPa, anderson" $paper "${P[@]}"
run units_paper_si units units_paper_cm:1e-2:1e4 1e-6 "paper scene in m, Pa, anderson" $paper "${P[@]}" "${SIP[@]}"
run units_paper_si_mono units units_paper_cm:1e-2:1e4 1e-6 "paper scene in m, Pa, monolithic" $paper "${P[@]}" "${SIP[@]}" "${MONO[@]}"
run units_paper_si_fixed units units_paper_cm:1e-2:1e4 1e-5 "paper scene in m, Pa, fixed gamma=0.02" $paper "${P[@]}" "${SIP[@]}" \
  --set "Contact solver/Domain decomposition/Relaxation=fixed" --set "Contact solver/Tolerance=1e-8"
run units_paper_cm_al units - - "paper scene in cm, MPa, augmented Lagrangian" $paper "${P[@]}" \
  --set "Contact pair S/Formulation=exact"
run units_paper_si_al units units_paper_cm_al:1e-2:1e4 1e-5 "paper scene in m, Pa, augmented Lagrangian" $paper "${P[@]}" "${SIP[@]}" \
  --set "Contact pair S/Formulation=exact"

# --- evaluate: python reads summary.json, parameters.prm and stdout.
python3 - "$work" "$manifest" doc/stability.csv <<'EOF'
import csv, json, math, os, re, sys

work, manifest, out_csv = sys.argv[1:4]

def read_prm(path):
    """ShortPRM of the run -> {'Body omega1/Material/Young's modulus': '...'}"""
    values, stack = {}, []
    for line in open(path):
        line = line.split('#')[0].strip()
        if line.startswith('subsection '):
            stack.append(line[len('subsection '):].strip())
        elif line == 'end':
            stack.pop()
        elif line.startswith('set '):
            key, value = line[4:].split('=', 1)
            values['/'.join(stack + [key.strip()])] = value.strip()
    return values

def constants(prm):
    c = {}
    for item in prm.get('Constants', '').split(','):
        if '=' in item:
            k, v = item.split('=')
            c[k.strip()] = float(v)
    return c

def closed_form(prm, theta):
    """Contact pressure of prm/stability/uniaxial.prm (see its header)."""
    c = constants(prm)
    def body(b):
        E = float(prm['Body %s/Material/Young\'s modulus' % b])
        nu = float(prm['Body %s/Material/Poisson\'s ratio' % b])
        y1 = float(prm['Body %s/Mesh/Corner 1' % b].split(',')[1])
        y2 = float(prm['Body %s/Mesh/Corner 2' % b].split(',')[1])
        x1 = float(prm['Body %s/Mesh/Corner 1' % b].split(',')[0])
        x2 = float(prm['Body %s/Mesh/Corner 2' % b].split(',')[0])
        return (1 - nu * nu) * (y2 - y1) / E, x2 - x1
    c1, L = body('omega1')
    c2, _ = body('omega2')
    g0 = float(eval(prm['Contact pair S/Gap'], {}, c))
    return max(c['Delta'] - g0, 0.) / (c1 + c2 + theta), L

results = {}
rows = []
for line in open(manifest):
    name, group, ref, tol, desc, code = line.rstrip('\n').split('\t')
    d = os.path.join(work, name)
    code = int(code)
    stderr = open(os.path.join(d, 'stderr')).read().strip().replace('\n', ' ')
    stdout = open(os.path.join(d, 'stdout')).read()
    r = dict(name=name, group=group, ref=ref, tol=tol, desc=desc, code=code,
             message=stderr, iterations='', answer='', reference='', error='',
             verdict='')
    summary = os.path.join(d, 'out', 'summary.json')
    s = json.load(open(summary)) if os.path.exists(summary) else None
    if s and s.get('status') == 'converged':
        newton = len(re.findall(r'^\s*Newton \d+:', stdout, re.M))
        r['iterations'] = ('N%d' % (newton - 1)) if newton else str(s.get('dd_iterations', ''))
        f = s['contact'][0]['force'][0]
        r['force'] = math.hypot(*f)
        r['u'] = s['points'][0]['u'] if s['points'] else None
        r['theta'] = s['theta'][0]
        r['prm'] = read_prm(os.path.join(d, 'out', 'parameters.prm'))
        finite = all(math.isfinite(x) for x in f + (r['u'] or []))
        r['finite'] = finite
    results[name] = r
    rows.append(r)

for r in rows:
    code, ref = r['code'], r['ref']
    if code == 124:
        r['verdict'] = 'FAIL hang (timeout)'
        continue
    if code >= 128 or code in (2, 3) or (code != 0 and not r['message'].startswith('ddcontact: error:')):
        r['verdict'] = 'FAIL crash/other error (exit %d)' % code
        continue
    if code in (1, 4):
        r['verdict'] = 'reported' if ref == 'report' else 'reported (stopped, not converged)'
        continue
    if 'force' not in r:
        r['verdict'] = 'FAIL no result'
        continue
    if not r['finite']:
        r['verdict'] = 'FAIL NaN'
        continue
    if ref == 'report':
        r['verdict'] = 'FAIL converged, divergence expected'
        r['answer'] = '%.6e' % r['force']
        continue
    if ref == '-':
        r['verdict'] = 'reference'
        r['answer'] = '%.6e' % r['force']
        continue
    tol = float(r['tol'])
    if ref == 'closed':
        p, L = closed_form(r['prm'], r['theta'])
        num = r['force'] / L
        r['answer'], r['reference'] = '%.9e' % num, '%.9e' % p
        err = abs(num - p) / p if p > 0 else num
        r['what'] = 'pressure' + ('' if p > 0 else ' (absolute)')
    else:
        parts = ref.split(':')
        other = results.get(parts[0])
        su = float(parts[1]) if len(parts) > 1 else 1.
        sf = float(parts[2]) if len(parts) > 2 else 1.
        if other is None or 'force' not in other:
            r['verdict'] = 'no reference (%s failed)' % parts[0]
            continue
        fr = other['force'] * sf
        ur = [x * su for x in other['u']]
        ef = abs(r['force'] - fr) / fr if fr > 0 else r['force']
        un = math.hypot(*ur)
        eu = math.hypot(r['u'][0] - ur[0], r['u'][1] - ur[1]) / un if un > 0 else 0.
        err = max(ef, eu)
        r['answer'] = 'F=%.9e u2=%.6e' % (r['force'], r['u'][1])
        r['reference'] = 'F=%.9e u2=%.6e' % (fr, ur[1])
    r['error'] = '%.2e' % err
    r['verdict'] = 'ok' if err <= tol else 'WRONG (error > %g)' % tol

fields = ['name', 'group', 'desc', 'code', 'iterations', 'answer', 'reference',
          'error', 'tol', 'verdict', 'message']
with open(out_csv, 'w', newline='') as f:
    w = csv.writer(f)
    w.writerow(fields)
    for r in rows:
        w.writerow([r[k] for k in fields])

bad = 0
counts = {}
print('%-26s %-14s %4s %7s %9s %6s  %s' % ('case', 'group', 'exit', 'iter', 'error', 'tol', 'verdict / message'))
for r in rows:
    bad += r['verdict'].startswith(('FAIL', 'WRONG', 'no reference'))
    key = r['verdict'].split(' (')[0]
    counts[key] = counts.get(key, 0) + 1
    msg = r['verdict'] + ('' if not r['message'] else ': ' + r['message'][18:140])
    print('%-26s %-14s %4d %7s %9s %6s  %s' % (r['name'], r['group'], r['code'], r['iterations'], r['error'], r['tol'], msg))
print('%d cases: %s; %d hang, crash, NaN or wrong answer' %
      (len(rows), ', '.join('%d %s' % (n, k) for k, n in sorted(counts.items())), bad))
sys.exit(1 if bad else 0)
EOF
status=$?
# The tables and counts of doc/stability.md follow the CSV.
python3 scripts/stability_tables.py || status=1
exit $status
