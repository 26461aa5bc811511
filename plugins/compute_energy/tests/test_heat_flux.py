"""Compute heat/flux: LAMMPS's heat flux vector, sum e_i v_i - sum S_i v_i, against LAMMPS's thermo:
LAMMPS 22 Jul 2025 printed HEAT_FLUX_LAMMPS on this machine for HEAT_FLUX (a two-type LJ solid
melting under nve: the whole flux and its convective part, a group's flux, the flux with the
stress's kinetic term included, and a variable that divides it by the volume, unnormalised)."""

import pytest

from pdps_core.testing import assert_prints_as_lammps, script_error

HEAT_FLUX = """units lj
atom_style atomic
lattice fcc 0.8
region box block 0 3 0 3 0 3
create_box 2 box
create_atoms 1 box
set type 1 type/fraction 2 0.3 4821
mass 1 1.0
mass 2 2.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
pair_coeff 2 2 1.2 1.1
neighbor 0.3 bin
group heavy type 2
compute myKE all ke/atom
compute myPE all pe/atom
compute myStress all stress/atom NULL virial
compute flux all heat/flux myKE myPE myStress
compute fluxheavy heavy heat/flux myKE myPE myStress
compute S all stress/atom NULL
compute fluxfull all heat/flux myKE myPE S
variable Jx equal c_flux[1]/vol
fix 1 all nve
thermo_style custom step temp pe c_flux[1] c_flux[2] c_flux[3] c_flux[4] c_flux[5] c_flux[6] &
    c_fluxheavy[1] c_fluxheavy[3] c_fluxheavy[5] c_fluxfull[2] v_Jx
thermo_modify format float %.15g
thermo 20
run 100
"""
HEAT_FLUX_LAMMPS = [
    [0, 1.5, -6.83813567764072, -0.37419354968934, 0.14278407785108, -0.164605551880447, -0.185327677633329, -0.0227417100505214, 0.00231320376489036, 0.267307459131755, 0.122995808857878, -0.0800125744150369, 0.0804592505979674, -0.299354839751472],
    [20, 0.715191727661127, -5.64953646541773, -0.941995587936503, 0.731164448068373, 0.363711017098302, -0.0661530726940168, -0.0288558923811208, 0.0296184929835626, -0.575975479907759, 0.265272621716608, -0.0590262651132745, 0.781186410831443, -0.753596470349203],
    [40, 0.823273905550253, -5.81279622159893, -0.932741790740399, -0.483965454060454, 0.59329562924969, -0.0560991480180061, 0.0920607933455005, 0.127243247190399, -0.352976952404608, -0.0994333463383904, -0.0262010223233894, -0.398618745429861, -0.74619343259232],
    [60, 0.823733441520725, -5.81754330646389, -0.646607824158556, -0.290397957762967, 0.459655141032389, -0.10642629560379, 0.0117560863198969, -0.0499358971019747, -0.534305180814461, 0.0708807656606511, 0.0419802140052257, -0.0840317590143678, -0.517286259326845],
    [80, 0.790375053305286, -5.77141790206045, -0.766112331871322, -1.43485239057551, -0.0256520471296374, -0.00270376962006088, -0.0758730552206277, -0.130867578029662, -0.644993924130512, -0.0028764668170469, 0.0161779191691186, -1.56423138535039, -0.612889865497058],
    [100, 0.787572592893559, -5.76429835162762, -0.585389484743396, 0.438434279141272, -0.302950512097256, 0.0663736503458589, -0.0877938389741485, 0.0907324150616252, -0.3845666874131, -0.209335514993215, 0.104704844654836, 0.235413488487771, -0.468311587794717],
]


def test_heat_flux_is_lammps(tmp_path):
    # the sums run in another order than LAMMPS's: round-off in the 13th digit
    assert_prints_as_lammps(tmp_path, HEAT_FLUX, HEAT_FLUX_LAMMPS, rel=1e-11, abs=1e-14)


SETUP = """units lj
atom_style atomic
lattice fcc 0.8
region box block 0 2 0 2 0 2
create_box 1 box
create_atoms 1 box
mass 1 1.0
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
compute k all ke/atom
compute e all pe/atom
compute s all stress/atom NULL
"""


@pytest.mark.parametrize("line, message", [
    ("compute f all heat/flux k e missing", "compute f heat/flux: compute missing is not defined"),
    ("compute f all heat/flux e k s", "compute f heat/flux: compute e is pe/atom, not ke/atom"),
    ("compute f all heat/flux k e k", "compute f heat/flux: compute k is ke/atom, not stress/atom"),
])
def test_inputs_are_checked(line, message):
    assert str(script_error(SETUP, line)) == f"<command>:1: compute: {message}"
