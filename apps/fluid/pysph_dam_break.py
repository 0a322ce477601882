"""The independent check of the dam-break front (docs/fluid-flow.md): PySPH's 2D dam break
(pysph.examples.dam_break_2d, PySPH 1.0b2 from PyPI) in the geometry of dam_break.par. The stock
example keeps the particle mass and h of dx = 0.03 whatever --dx says and makes the column
1 + dx wide; here the column is exactly L = 1 wide and 2 L high, its first rows dx/2 from the
wall surfaces (the innermost wall layer at x = 0 and y = 0), with m = rho0 dx^2 and h = hdx dx.
Writes <output dir>/front.TZ: T = t sqrt(2 g / L) and Z / L = the largest fluid x (the front's
distance from the wall surface, as the fluid app's largest x + dx/2).

    python3 -m venv venv-pysph && venv-pysph/bin/pip install pysph
    venv-pysph/bin/python apps/fluid/pysph_dam_break.py --dx 0.02 --tf 0.64 --pfreq 50 -d pysph50
    /usr/bin/python3 apps/fluid/front_errors.py pysph50/front.TZ
"""
import numpy as np
from pysph.base.utils import get_particle_array
from pysph.examples.dam_break_2d import DamBreak2D
from pysph.tools.geometry import get_2d_tank


class MatchedDamBreak(DamBreak2D):
    def create_particles(self):
        dx, h, rho0 = self.dx, self.h, 1000.0
        xt, yt = get_2d_tank(dx=dx, length=4.0, height=4.0, base_center=[2, 0], num_layers=4)
        n = int(round(1.0 / dx))
        i, j = np.meshgrid(np.arange(n), np.arange(2 * n), indexing="ij")
        xf, yf = (i.ravel() + 1.0) * dx, (j.ravel() + 1.0) * dx
        fluid = get_particle_array(name="fluid", x=xf, y=yf, h=h, m=dx * dx * rho0, rho=rho0)
        boundary = get_particle_array(name="boundary", x=xt, y=yt, h=h, m=dx * dx * rho0, rho=rho0)
        self.scheme.setup_properties([fluid, boundary])
        return [fluid, boundary]

    def post_process(self, info_fname):
        from pysph.solver.utils import iter_output
        self.read_info(info_fname)
        rows = [(data["t"] * np.sqrt(2 * 9.81), array.get("x").max())
                for data, array in iter_output(self.output_files, "fluid")]
        np.savetxt(self.output_dir + "/front.TZ", np.array(rows), header="T = t sqrt(2 g / L), Z / L")


if __name__ == "__main__":
    app = MatchedDamBreak()
    app.run()
    app.post_process(app.info_filename)
