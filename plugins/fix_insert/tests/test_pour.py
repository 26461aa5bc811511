"""LAMMPS's fix pour: batches of the size and on the steps LAMMPS inserts them, the first batch's
positions, radii, masses and velocities to round-off, and the thermo of short pours to the digits
LAMMPS prints (block and cylinder, one, range and poly diameters, rate, 2-d); the same on 1 and 2
ranks; bad input gets one line.

Every reference number was recorded on this machine with LAMMPS 22 Jul 2025 (Update 4) running the
scripts below (``lmp -in SCRIPT -log none``; the dumps and thermo with ``%20.16g`` / ``%20.15g``).
"""

import numpy as np
import pytest

from pdps_core.testing import run_ranks

MATERIAL = """
    newton off
    comm_modify vel yes
    neighbor 0.2 bin
    neigh_modify delay 0
    pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
    pair_coeff * *
    fix 1 all nve/sphere
"""

OUTPUT = """
    compute 1 all erotate/sphere
    thermo_style custom step atoms ke c_1
    thermo_modify norm no lost ignore
    thermo_modify format float %20.15g
    compute_modify thermo_temp dynamic/dof yes
"""

BOX = """
    atom_style sphere
    boundary p p fm
    region box block 0 8 0 8 0 12 units box
    create_box 1 box
""" + MATERIAL + """
    timestep 0.001
    fix 2 all gravity 1.0 vector 0 0 -1
    fix zlower all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 2000.0
    region slab block 1 7 1 7 8 11 units box
    fix ins all pour 150 1 4321 vol 0.2 30 diam range 0.8 1.0 dens 1.0 2.0 vel -0.5 0.5 -0.2 0.3 -1.0 region slab
""" + OUTPUT + """
    dump d all custom 1 first.dump id type radius mass x y z vx vy vz
    dump_modify d format float %20.16g
    run 1
    undump d
    thermo 100
    run {steps}
"""

# LAMMPS's dump at step 1 of BOX: id, radius, mass, x, y, z, vx, vy, vz
FIRST_BATCH = np.array([
    (1, 0.4457729480908126, 0.6052722361024601, 1.356313737275225, 1.564982384706374, 10.26103348205863, 0.1098232933365848, -0.04995444600933904, -1.574645176240975),
    (2, 0.4272542892616495, 0.4085577626791098, 4.77037723258621, 3.730148076419788, 10.39328329790079, 0.09978673122813309, 0.1077958756162766, -1.488261205368126),
    (3, 0.4075700221152837, 0.2903807232083985, 2.761701494344371, 5.917015445845674, 10.86547118852274, -0.1202336119582102, 0.1668419091807873, -1.127024577163999),
    (4, 0.4423327926277801, 0.6426865956562021, 6.234741706044758, 3.303853494256667, 10.76654967067387, -0.02238700470066957, -0.07919400207660814, -1.211656744047713),
    (5, 0.4698459333134098, 0.4389904940206804, 6.38544939802282, 4.248032569535091, 9.579112537582297, -0.2194339706187295, 0.03662790550693304, -1.960544623174535),
    (6, 0.4289324076515308, 0.5306099137237018, 5.018523956657631, 4.332139544809301, 10.99030806030696, 0.3782216016567412, -0.06477047757467744, -1.010145422604429),
    (7, 0.487040961388052, 0.7570341079287891, 4.018761413646285, 1.323079153114501, 10.9955559859317, 0.4985543992363636, 0.1518939827810479, -1.004934183078511),
    (8, 0.4695856316339158, 0.6595223033039328, 2.54265227333766, 2.356757986059765, 9.005581577990696, 0.005245284412636053, 0.1287475615873688, -2.234070425130716),
    (9, 0.4616632170331028, 0.659869950881061, 5.421320521468911, 6.134004327996636, 9.790059386648672, -0.2982098934232303, 0.04316061788385761, -1.849792087990066),
    (10, 0.4719933369066535, 0.6844624935948695, 6.520803407542782, 5.142870571530829, 10.91585830973136, 0.3709492864417607, -0.177671386663649, -1.081371583740308),
    (11, 0.4120437623989041, 0.5783877988927896, 1.683062727881159, 3.235267498640003, 10.84944381541392, -0.1431917262464723, 0.2383284877698535, -1.141163126945091),
    (12, 0.4355464942918841, 0.5175420463664782, 2.795773821787804, 2.570622787610918, 10.38392261863234, 0.07619856278235027, -0.1153776585196041, -1.494539746036001),
    (13, 0.4161190721281428, 0.4983643210596475, 1.794715461691243, 1.782764644726536, 8.227846913901807, 0.1542306531473205, 0.1272937235083867, -2.558684155254736),
    (14, 0.4686651132389275, 0.7470175698215785, 3.167090260501527, 3.286008249170151, 10.97658951225085, -0.009892699546130701, -0.083300635909336, -1.023642695570024),
    (15, 0.4321539088767739, 0.4862101495943333, 6.167947004161751, 2.685298946539545, 8.784790148763504, 0.3032324150219711, 0.2635996371338142, -2.330826093591408),
    (16, 0.4075914327556228, 0.3040665459932331, 6.352619425092181, 4.474677524284775, 8.722155311351717, -0.3491415576306831, 0.03892045055465793, -2.357550991662371),
    (17, 0.4067417184853655, 0.3073416109710968, 4.654952527794499, 1.787134642147987, 10.17866479971144, 0.3953217635375084, 0.1364398874512128, -1.626129232198144),
    (18, 0.4865644470260313, 0.8721824916632269, 6.159659307990064, 1.393989389014425, 8.220049956923976, 0.1299435275746247, 0.03043397335821482, -2.561730189996996),
    (19, 0.4382774667061295, 0.5355317696653923, 3.697363628399262, 5.590502506396968, 10.99992965943704, 0.2626041689713505, -0.1558660492561134, -1.000570338089238),
    (20, 0.4792692053966546, 0.4906109068146927, 5.099006331571847, 6.999414728022839, 10.38853476747351, -0.1394443533566987, 0.2293765669825378, -1.491449517942501),
    (21, 0.451740861102818, 0.5159887460176622, 1.519153303708487, 2.409575428538758, 10.64019761351965, -0.04429542484893251, -0.1866027180043062, -1.311837017307415),
    (22, 0.4216628321081692, 0.5151732485930721, 6.233154520035328, 6.628018233751886, 10.94507064292349, -0.4829242220068929, 0.2963003650756089, -1.053998321855812),
    (23, 0.4239726816881321, 0.3248264490178412, 6.726363399869932, 3.989661613940104, 10.50293810343952, 0.04045758188723469, 0.03528938937712897, -1.412634481244953),
    (24, 0.4697847527311113, 0.770901804651, 5.340349107207893, 1.247444843057285, 9.518533031059444, -0.3657537893698335, -0.06196896939630109, -1.991211917350451),
    (25, 0.4770714620952827, 0.5820573585517276, 6.707634447937661, 1.212166488269421, 10.31163977025755, -0.1863052759721434, -0.06638663190714394, -1.542161590455213),
    (26, 0.4979297563889668, 0.8920124940495916, 4.205752833376524, 6.087870559230386, 8.865440500910346, 0.4734148308510961, -0.1084689428137936, -2.295956163419226),
    (27, 0.4249929861281966, 0.3400526632038924, 4.92437002152408, 5.886951755213994, 10.65357981759307, -0.3336416863993005, 0.2920883434787804, -1.301591989374253),
    (28, 0.4936584179260109, 0.556946481189597, 3.279427116866888, 1.331553181787745, 9.494797166388233, 0.2357210511042369, -0.06814704554534848, -2.003099727160556),
    (29, 0.4342212015456619, 0.630059832248725, 4.344062676347821, 2.661401377833169, 10.76155199086309, 0.3621595403468979, -0.04230269484329163, -1.215776107834683),
    (30, 0.4448872230690379, 0.57608524899771, 2.173487279179267, 1.800701165944664, 10.98005350785904, 0.397416005328957, 0.2354007818900983, -1.020251432596163),
    (31, 0.4036450394911901, 0.5167366311745184, 6.788052623061487, 2.800435794424469, 10.0645667949275, -0.1792671846594974, 0.07821371391332416, -1.694863128182682),
    (32, 0.4382113114177302, 0.6676348723453694, 3.733146436853868, 6.992164202962147, 10.84709454363217, -0.4493734691987622, 0.2400515882019194, -1.143220837622061),
    (33, 0.4439220837521936, 0.5316843641524247, 6.90769738699668, 3.669983253194943, 8.568027100607935, -0.4319105920996101, -0.01066070907314343, -2.422058547461558),
    (34, 0.4488464166637726, 0.7034110023104267, 1.524497297836699, 2.226084741403388, 9.529603022556856, -0.03229187220907392, 0.1852518910473454, -1.98564330840025),
    (35, 0.4262726196210239, 0.3987732636753477, 4.835078232844863, 5.159859423600072, 9.518893036150642, -0.04044459226561925, 0.1738688958687097, -1.991031066750458),
    (36, 0.4347582477306753, 0.4124330649533278, 5.912176567554556, 5.951570889424333, 8.528036785013743, -0.3246769075396829, 0.1276074902748724, -2.438516905185958),
    (37, 0.4019736958676827, 0.4552279765824488, 5.314386888553568, 2.900435919827054, 9.177984213090198, -0.06224924445257024, -0.06152575717378678, -2.155501525247628),
    (38, 0.4461149286693498, 0.7323352891828535, 4.216368745647543, 4.509508098247232, 10.40634652223856, 0.2171012068712623, -0.04000805734657129, -1.479454683390566),
    (39, 0.4851995905792339, 0.8881508146245956, 1.84272079767786, 4.608446571793615, 9.62077711404099, 0.3602553558816459, -0.04411684858804424, -1.93917113557664),
    (40, 0.4036160202248097, 0.3587754001134028, 5.467115102553328, 1.803528613785062, 10.99880074128941, 0.3175686475902649, 0.2381300247917557, -1.001698540460976),
    (41, 0.4423668474156255, 0.6821147728270891, 5.621446157163683, 3.645563450011221, 9.5515306576785, 0.1641507230997787, -0.009398431009332853, -1.974566535009142),
])

# LAMMPS's thermo of BOX (steps 1999): step, atoms, ke, c_1 (erotate/sphere). The second run starts
# with a batch on its first step (LAMMPS's setup_pre_exchange): 30 of 41 fit beside the first batch
# (LAMMPS warns), then 41 at step 2 + 1646.
BOX_THERMO = np.array([
    (1, 41, 35.8921336723558, 0),
    (100, 71, 70.0344104294419, 6.97951606670613e-05),
    (200, 71, 77.3391370670446, 0.0110944980044146),
    (300, 71, 85.0375358500678, 0.0545374975949777),
    (500, 71, 101.893531249359, 0.0567932465694743),
    (800, 71, 130.18551059935, 0.0754435129813979),
    (1000, 71, 151.153466006168, 0.0754435129813979),
    (1200, 71, 173.671410848348, 0.104567138242615),
    (1600, 71, 223.782570576712, 0.10096547485816),
    (1700, 112, 277.853612880018, 0.101760869333604),
    (2000, 112, 334.443841950281, 0.12173722339863),
])

CYLINDER = """
    atom_style sphere
    boundary p p fm
    region box block -5 5 -5 5 0 10 units box
    create_box 2 box
""" + MATERIAL + """
    timestep 0.002
    fix 2 all gravity 5.0 vector 0 0 -1
    fix zlower all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 2000.0
    region cyl cylinder z 0.5 -0.5 4.0 6 7 units box
    fix ins all pour 70 2 98765 vol 0.1 20 diam poly 3 0.6 0.5 0.8 0.3 1.0 0.2 dens 1.5 2.5 &
        vel 0 0.2 -0.3 0 -1.0 rate -0.5 id next ignore region cyl
""" + OUTPUT + """
    thermo 1
    dump d all custom 900 cyl.dump id type radius mass x y z vx vy vz
    run 900
"""

# LAMMPS: "Particle insertion: 20 every 270 steps, 70 by step 811"; the atom count changes only at
# steps 1, 271, 541, 811 (thermo every step); the radii at step 900 are 0.3, 0.4, 0.5, all of type 2
CYLINDER_BATCHES = [(1, 20), (271, 40), (541, 60), (811, 70)]
CYLINDER_THERMO = np.array([
    (1, 20, 21.5371185165109, 0.0),
    (100, 20, 46.7633245852199, 0.0),
    (270, 20, 115.186108886185, 0.0),
    (271, 40, 146.764924935552, 0.0),
    (300, 40, 169.161704326682, 0.0),
    (541, 60, 366.346911489018, 0.00162349045237105),
    (600, 60, 424.042055682146, 0.00272316689094079),
    (811, 70, 248.297246849221, 12.3729488489068),
    (900, 70, 255.226271585139, 14.9331160971015),
])

TWO_D = """
    dimension 2
    atom_style sphere
    boundary p fm p
    region box block 0 20 0 20 -0.5 0.5 units box
    create_box 1 box
""" + MATERIAL + """
    timestep 0.001
    fix 2 all gravity 1.0 spherical 0.0 -180.0
    fix 3 all enforce2d
    fix ylower all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 yplane 0.0 2000.0
    region slab block 1 19 15 19 -0.5 0.5 units box
    fix ins all pour 60 1 1234 vol 0.3 40 diam range 0.5 1.0 vel -1 1 -2 region slab
""" + OUTPUT + """
    thermo 1
    run 1
    run 2500
"""

# LAMMPS: "Particle insertion: 27 every 1464 steps, 60 by step 2929"; the second run's first batch
# places 21 of 27 (LAMMPS warns), the third the last 12
TWO_D_BATCHES = [(1, 27), (2, 48), (1466, 60)]
TWO_D_THERMO = np.array([
    (1, 27, 20.6162010910482, 0.0),
    (2, 48, 39.76797862175, 0.0),
    (500, 48, 54.7891104113596, 0.0685610454846402),
    (1000, 48, 73.3682526421003, 0.084514145460973),
    (1465, 48, 93.0565076435871, 0.106526293351838),
    (1466, 60, 101.67577336285, 0.106526293351838),
    (2000, 60, 131.544550770491, 0.112251682758288),
    (2501, 60, 163.244720054579, 0.113179017937066),
])


def thermo(text):
    """{step: row} of every thermo line (the last line of a step printed twice across runs)."""
    rows, inside = {}, False
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            inside = True
            continue
        if not inside or words[:1] == ["WARNING:"]:
            continue
        try:
            row = [float(w) for w in words]
        except ValueError:
            inside = False
            continue
        rows[int(row[0])] = np.array(row)
    return rows


def batches(rows):
    """(step, atoms) where the atom count changes."""
    out, previous = [], 0
    for step in sorted(rows):
        if rows[step][1] != previous:
            previous = rows[step][1]
            out.append((step, int(previous)))
    return out


def agrees(rows, reference):
    for ref in reference:
        row = rows[int(ref[0])]
        assert row[1] == ref[1], f"step {int(ref[0])}: {row[1]:g} particles, LAMMPS {ref[1]:g}"
        # printed to 15 digits: agreement to the last one or two
        np.testing.assert_allclose(row[2:], ref[2:], rtol=2e-13, atol=1e-15, err_msg=f"step {int(ref[0])}")


def last_frame(path):
    frame = path.read_text().split("ITEM: ATOMS")[-1].splitlines()
    values = np.loadtxt(frame[1:], ndmin=2)
    return values[np.argsort(values[:, 0])]


def test_the_first_batch_is_lammps_s_to_round_off(pdps_cli, tmp_path):
    """41 spheres (vol 0.2 of a 6 x 6 x 3 slab / the largest sphere), their diameters, densities and
    velocities drawn in LAMMPS's order from its Park-Miller stream: after one step, LAMMPS's dump."""
    result = pdps_cli(BOX.format(steps=1999), name="in.box")
    assert result.returncode == 0, result.stderr
    assert "Particle insertion: 41 every 1646 steps, 150 by step 4939" in result.stdout
    got = last_frame(tmp_path / "first.dump")
    assert len(got) == 41
    assert np.array_equal(got[:, 0], FIRST_BATCH[:, 0]) and (got[:, 1] == 1).all()
    np.testing.assert_allclose(got[:, 2:], FIRST_BATCH[:, 1:], rtol=0, atol=1e-12)
    assert "inserted 30 of 41 particles at step 2" in result.stdout + result.stderr
    agrees(thermo(result.stdout), BOX_THERMO)


def test_a_cylinder_pours_lammps_s_batches_on_its_steps(pdps_cli, tmp_path):
    """diam poly, dens, vel, a falling region (rate), id next and ignore (LAMMPS recorded the same with
    and without it): LAMMPS's counts on LAMMPS's steps,
    and its thermo through contacts with the floor."""
    result = pdps_cli(CYLINDER, name="in.cyl")
    assert result.returncode == 0, result.stderr
    assert "Particle insertion: 20 every 270 steps, 70 by step 811" in result.stdout
    rows = thermo(result.stdout)
    assert batches(rows) == CYLINDER_BATCHES
    agrees(rows, CYLINDER_THERMO)
    last = last_frame(tmp_path / "cyl.dump")
    assert sorted(set(last[:, 2])) == [0.3, 0.4, 0.5] and (last[:, 1] == 2).all()
    assert np.array_equal(last[:, 0], np.arange(1, 71))


def test_in_2d_the_stream_falls_along_y(pdps_cli):
    result = pdps_cli(TWO_D, name="in.2d")
    assert result.returncode == 0, result.stderr
    assert "Particle insertion: 27 every 1464 steps, 60 by step 2929" in result.stdout
    rows = thermo(result.stdout)
    assert batches(rows) == TWO_D_BATCHES
    agrees(rows, TWO_D_THERMO)


def test_the_same_pour_on_1_and_2_ranks(tmp_path):
    """Every rank draws the whole batch from the one stream and rank 0 adds it, as LAMMPS's ranks
    all draw it (and each keeps its own): LAMMPS's numbers on 2 ranks too."""
    script = BOX.format(steps=299)
    for ranks in (1, 2):
        folder = tmp_path / str(ranks)
        folder.mkdir()
        rows = thermo(run_ranks(script, ranks, folder).stdout)
        agrees(rows, BOX_THERMO[BOX_THERMO[:, 0] <= 300])
        np.testing.assert_allclose(last_frame(folder / "first.dump")[:, 2:], FIRST_BATCH[:, 1:], rtol=0, atol=1e-12)


BAD = """
    atom_style sphere
    boundary p p fm
    region box block 0 8 0 8 0 12 units box
    create_box 1 box
    timestep 0.001
    {gravity}
    region slab block 1 7 1 7 8 11 units box
    region wide block -1 7 1 7 8 11 units box
    region ball sphere 4 4 9 1 units box
    region sideways cylinder x 4 9 1 1 7 units box
    fix ins all pour {args}
"""
GRAVITY = "fix 2 all gravity 1.0 vector 0 0 -1"


@pytest.mark.parametrize("args, message", [
    ("10 1 5 region slab mol m1", "fix: molecule template m1 is not defined (defined: none)"),
    ("10 1 5 region slab rigid r1", "fix: rigid needs mol: fix pour makes rigid bodies of molecules only (LAMMPS: "
     "Cannot use fix pour rigid and not molecule)"),
    ("10 1 5 region slab shake s1", "fix: keyword shake of fix pour: pdps has no fix shake"),
    ("10 1 5 region slab molfrac 1", "fix: keyword molfrac of fix pour: pdps's molecule templates are one molecule "
     "each (LAMMPS's molfrac chooses among a set's)"),
    ("10 0 5 region slab", "fix: TYPE must be from 1 to 1 (got 0)"),
    ("10 1 5 diam one 1", "fix: missing keyword region; usage: fix ID GROUP pour N TYPE SEED region ID "
     "[diam one D | range DLO DHI | poly N D1 P1 ...] [dens DLO DHI] [vol FRAC MAXATTEMPT] [rate V] "
     "[vel VXLO VXHI VYLO VYHI VZ | VXLO VXHI VY] [id max|next] [ignore] [mol TEMPLATE [rigid FIX_ID]]"),
    ("10 1 5 region slab bogus 3", "fix: unknown keyword bogus (known: region, diam, dens, vol, rate, vel, id, ignore, mol, rigid)"),
    ("10 1 5 region slab diam poly 2 1.0 0.5 0.8 0.4", "fix: diam poly: the fractions must sum to 1 (got 0.9)"),
    ("10 1 5 region slab diam poly 2 1.0 0.5", "fix: diam poly 2 needs 4 values, a diameter and a fraction each "
     "(got 2)"),
    ("10 1 5 region slab diam range 1.0 0.5", "fix: diam range: need 0 < DLO <= DHI (got 1 0.5)"),
    ("10 1 5 region slab dens 2 1", "fix: dens: DLO must be <= DHI (got 2 1)"),
    ("10 1 5 region slab vel 0 1 2", "fix: vel takes VXLO VXHI VYLO VYHI VZ in 3-d (got 3 values)"),
    ("10 1 5 region slab vel 1 0 0 0 -1", "fix: vel: need VXLO <= VXHI and VYLO <= VYHI (got 1 0 0 0 -1)"),
    ("10 1 5 region slab id later", "fix: id must be one of 'max' or 'next' (got later)"),
    ("10 2 5 region slab", "fix: TYPE must be from 1 to 1 (got 2)"),
    ("10 1 0 region slab", "fix: seed must be >= 1 (got 0)"),
    ("10 1 5 region wide", "fix: region wide extends outside the simulation box (fix pour inserts inside it)"),
    ("10 1 5 region ball", "fix: region ball is a sphere: fix pour needs a block or cylinder region"),
    ("10 1 5 region sideways", "fix: region sideways: fix pour needs a z-axis cylinder (got x)"),
    ("10 1 5 region slab vol 0.0001 5", "fix: fix pour inserts 0 particles each time (vol FRAC times the region's "
     "volume is less than one particle's)"),
])
def test_bad_input_gets_one_line(pdps_cli, args, message):
    result = pdps_cli(BAD.format(gravity=GRAVITY, args=args), name="in.bad")
    assert result.returncode == 1
    assert result.stderr.strip() == f"ERROR: in.bad:12: {message}"


def test_pour_needs_a_gravity_at_its_first_run(pdps_cli):
    result = pdps_cli(BAD.format(gravity="", args="10 1 5 region slab") + "run 1\n", name="in.bad")
    assert result.returncode == 1
    assert result.stderr.strip() == ("ERROR: in.bad:13: run: fix ins (pour) needs a fix gravity (LAMMPS: No fix "
                                     "gravity defined for fix pour)")


# LAMMPS's thermo of BOX with the fix gravity and "timestep 0.002" given after the fix pour: LAMMPS
# takes both at the first run ("Particle insertion: 41 every 823 steps, 150 by step 2470")
LATE_THERMO = np.array([
    (1, 41, 35.911272429653, 0),
    (500, 71, 151.050076434256, 0.0772130129043982),
    (1000, 112, 334.228778626066, 0.124122677429796),
    (1700, 150, 278.861022641657, 10.8382503337614),
    (2000, 150, 197.416542497777, 15.4123668233667),
])


def test_gravity_and_timestep_given_after_the_pour_count_as_lammps_s(pdps_cli):
    script = BOX.format(steps=1999).replace("    timestep 0.001\n", "").replace(
        "    fix 2 all gravity 1.0 vector 0 0 -1\n", "")
    script = script.replace("    compute 1 all erotate/sphere\n",
                            "    fix 2 all gravity 1.0 vector 0 0 -1\n    timestep 0.002\n    compute 1 all erotate/sphere\n")
    result = pdps_cli(script, name="in.late")
    assert result.returncode == 0, result.stderr
    assert "Particle insertion: 41 every 823 steps, 150 by step 2470" in result.stdout
    agrees(thermo(result.stdout), LATE_THERMO)


def test_a_timestep_changed_after_the_first_run_is_refused(pdps_cli):
    """LAMMPS (recorded): ERROR: Cannot change timestep with fix pour."""
    script = BAD.format(gravity=GRAVITY, args="10 1 5 region slab") + "run 1\ntimestep 0.002\nrun 1\n"
    result = pdps_cli(script, name="in.bad")
    assert result.returncode == 1
    assert result.stderr.strip().endswith("fix ins (pour): the time step changed since its first run (0.001, now "
                                          "0.002; LAMMPS: Cannot change timestep with fix pour)")


def test_gravity_must_point_down(pdps_cli):
    script = BAD.format(gravity="fix 2 all gravity 1.0 vector 1 0 -1", args="10 1 5 region slab") + "run 1\n"
    result = pdps_cli(script, name="in.bad")
    assert result.returncode == 1
    assert result.stderr.strip().endswith("fix ins (pour): gravity must point along -z in 3-d (got 0.707107 0 "
                                          "-0.707107)")


def test_a_gravity_changed_after_the_first_run_is_refused(pdps_cli):
    """nfreq was worked out from the gravity of the first run; LAMMPS stops when it has changed."""
    script = BAD.format(gravity=GRAVITY, args="10 1 5 region slab") + ("run 1\nfix 2 all gravity 2.0 vector 0 0 -1\n"
                                                                      "run 1\n")
    result = pdps_cli(script, name="in.bad")
    assert result.returncode == 1
    assert result.stderr.strip().endswith("fix ins (pour): gravity changed since its first run")
