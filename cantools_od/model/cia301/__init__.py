"""CiA 301 communication profile: the one place for its numbers and rules."""
