"""Denavit: a kinematics service for robot arms."""
