"""pdps plugin: the cohesion sub-model ``vdw`` of LIGGGHTS's granular contacts (pdps_contact_vdw.vdw),
the plugin guide's worked example of a contact sub-model in a distribution of its own."""

PDPS_API = ">=1.0,<2"
