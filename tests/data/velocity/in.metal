units metal
atom_style atomic
boundary p p p
read_data metal.data
velocity all create 300.0 8675309 dist gaussian
