"""Writes the bad initial-data files the bad-input tests feed to the apps (into the current folder).

Each file is a well-formed H5Part file (Step#0 with TimeValue) of 1-D particles broken in one way:
  zero_particles.h5part   a step with no particles
  negative_h.h5part       h < 0 for particle 3
  negative_rho.h5part     rho < 0 for particle 5
  nan_position.h5part     x = NaN for particle 7
  missing_mass.h5part     no dataset m
  text_positions.h5part   x holds strings
  coincident.h5part       particles 4 and 9 at one position
  walls_only.h5part       every particle a wall (kind 1)
  single_particle.h5part  one particle
  duplicate_ids.h5part    particles 2 and 11 with id 2
  nan_ids.h5part          ids as float64, NaN for particle 6
  fractional_ids.h5part   ids as float64, 6.5 for particle 6
and two that are not usable HDF5 files:
  truncated.h5part        the first half of a valid file
  not_hdf5.h5part         a text file
"""
import h5py
import numpy as np

COUNT = 16


def valid_particles(count=COUNT):
    x = np.linspace(-0.5, 0.5, count)
    return {
        "x": x, "y": np.zeros(count), "z": np.zeros(count),
        "vx": np.zeros(count), "m": np.full(count, 1.0 / COUNT), "h": np.full(count, 2.0 / COUNT),
        "u": np.full(count, 2.5), "rho": np.ones(count), "id": np.arange(count, dtype=np.int64),
    }


def write(path, particles):
    with h5py.File(path, "w") as f:
        step = f.create_group("Step#0")
        step.attrs["TimeValue"] = 0.0
        for name, values in particles.items():
            step.create_dataset(name, data=values)


def broken(change):
    particles = valid_particles()
    change(particles)
    return particles


write("zero_particles.h5part", valid_particles(0))
write("negative_h.h5part", broken(lambda p: p["h"].__setitem__(3, -0.01)))
write("negative_rho.h5part", broken(lambda p: p["rho"].__setitem__(5, -1.0)))
write("nan_position.h5part", broken(lambda p: p["x"].__setitem__(7, np.nan)))
write("missing_mass.h5part", broken(lambda p: p.pop("m")))
write("text_positions.h5part", broken(lambda p: p.__setitem__("x", np.array([b"left"] * COUNT))))
write("coincident.h5part", broken(lambda p: p["x"].__setitem__(9, p["x"][4])))
write("walls_only.h5part", broken(lambda p: p.__setitem__("kind", np.ones(COUNT, dtype=np.int32))))
write("single_particle.h5part", valid_particles(1))
write("duplicate_ids.h5part", broken(lambda p: p["id"].__setitem__(11, 2)))
write("nan_ids.h5part", broken(lambda p: (p.__setitem__("id", p["id"].astype(np.float64)), p["id"].__setitem__(6, np.nan))))
write("fractional_ids.h5part", broken(lambda p: (p.__setitem__("id", p["id"].astype(np.float64)), p["id"].__setitem__(6, 6.5))))

write("valid.h5part", valid_particles(4096))
with open("valid.h5part", "rb") as source:
    data = source.read()
with open("truncated.h5part", "wb") as target:
    target.write(data[: len(data) // 2])
with open("not_hdf5.h5part", "w") as target:
    target.write("x y z\n0 0 0\n")
