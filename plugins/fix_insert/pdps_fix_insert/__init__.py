"""pdps plugin: particle insertion during a run, as LIGGGHTS's users write it. Templates say what a
particle is (particletemplate_sphere.py), a distribution mixes templates by mass
(particledistribution_discrete.py), and the insertion fixes say where and when (insert_pack.py,
insert_rate_region.py, insert_stream.py, on the machinery of insertion.py and placement.py)."""

PDPS_API = ">=1.0,<2"
