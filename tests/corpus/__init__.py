"""A corpus of real robot description packages, uploaded through HTTP as a lab would."""
