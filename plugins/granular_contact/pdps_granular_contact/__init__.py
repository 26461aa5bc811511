"""pdps granular contact laws: a library the granular packs depend on (no styles, no entry points).

``contact_models`` holds the laws as numba functions over scalars and 3-vectors; the per-contact history
they update is the core's ``pdps_core.api.ContactHistory``.
"""
