"""Reachability maps (course, after Vahrenkamp et al.): a 6-D grid of frame poses.

One concept per module:

- :mod:`.bins`: orientation bins (cubed 3-sphere, equal-angle): ``orientation_bins``,
  ``orientation_bin``, ``orientation_bin_from_rotation``;
- :mod:`.spec`: the grid, sampling and measure of a map: ``MapSpec``, ``make_spec``
  (validates a build request), ``default_bounds``, ``default_voxel_size``, ``voxel_index``, the
  limits ``MAX_CELLS``, ``MAX_SAMPLES``, ``MAX_ORIENTATION_DIVISIONS``;
- :mod:`.build`: sampling and building in the calling thread: ``build_map``,
  ``MapBuilder``, ``Progress`` (over worker processes: :mod:`app.workers.map_build`);
- :mod:`.map`: a finished map: ``ReachabilityMap`` (bytes format, queries),
  ``summarize``, ``meta_public``, ``robot_fingerprint``.

The vectorised FK and Jacobian are :mod:`app.kinematics.chain`'s, the batched Yoshikawa
measure :func:`app.kinematics.analysis.yoshikawa_components`. Storage of finished maps
(:mod:`app.storage.maps`) and build jobs (:mod:`app.storage.build_jobs`) belong to the app, not
here.
"""
