package tactus.export;

import static tactus.export.FaustNumbers.lit;

import tactus.linkModuleType;

/**
 * Writes any exportable model as Tactus's explicit scheme in plain Faust: three signals per mass (a constant for
 * a coordinate that cannot move), distance-based interactions with {@code sqrt}, each damper fed with the
 * distance of the previous step. The helper functions it writes at the top of the program are the equations of
 * docs/modules.md, term for term.
 */
final class ExplicitWriter {
    private ExplicitWriter() {
    }

    /** The helper functions every explicit program starts with (our own code; see docs/modules.md). */
    static final String HELPERS = String.join("\n",
            "// One coordinate of a mass (Tactus's scheme, docs/modules.md), from q(-1) = q0 and q(-2) = qr0:",
            "//   q(n) = q(n-1) + d (q(n-1) - q(n-2)) - kc (q(n-1) - r) + c f(n) + g",
            "coord(d, kc, r, c, g, q0, qr0) = step ~ _",
            "with {",
            "  step(q, f) = p1 + d*(p1 - p2) - kc*(p1 - r) + f*c + g",
            "  with { p1 = q + q0*i0; p2 = q' + qr0*i0 + q0*i0'; };",
            "};",
            "// a free mass m in air friction fr (retention 1 - fr/m) and gravity g; an oscillator (spring k, damper z)",
            "mass(m, fr, g, q0, qr0) = coord(1 - fr*(1/m), 0, 0, 1/m, g, q0, qr0);",
            "osc(m, k, z, fr, g, r, q0, qr0) = coord(1 - (z + fr)*(1/m), k*(1/m), r, 1/m, g, q0, qr0);",
            "",
            "// An interaction adds s (x1 - x2) to mass 1 and -s (x1 - x2) to mass 2 (s: scalar force over distance)",
            "push(dx, dy, dz, s) = s*dx, s*dy, s*dz, 0 - s*dx, 0 - s*dy, 0 - s*dz;",
            "// the value of a signal one step before; d0 at the first sample",
            "prev(d0, d) = d' + d0*i0;",
            "link(law, x1, y1, z1, x2, y2, z2) = push(dx, dy, dz, law(dx*dx + dy*dy + dz*dz))",
            "with { dx = x1 - x2; dy = y1 - y2; dz = z1 - z2; };",
            "spring(k, l0, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2(d > 0, 0, 0 - k*(d - l0)/d) with { d = sqrt(d2); }; };",
            "damper(z, d0, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2(d > 0, 0, 0 - z*(d - prev(d0, d))/d) with { d = sqrt(d2); }; };",
            "springDamper(k, z, l0, d0, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2(d > 0, 0, (0 - k*(d - l0) - z*(d - prev(d0, d)))/d) with { d = sqrt(d2); }; };",
            "// rope and bubble: only while d > l0; contact: only while 0 < d < l0",
            "stretched(k, z, l0, d0, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2(d2 > l0*l0, 0, (0 - k*(d - l0) - z*(d - prev(d0, d)))/d) with { d = sqrt(d2); }; };",
            "contact(k, z, l0, d0, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2((d2 < l0*l0) & (d > 0), 0, (0 - k*(d - l0) - z*(d - prev(d0, d)))/d)",
            "  with { d = sqrt(d2); }; };",
            "attractor(a, lim, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2((d2 > lim*lim) & (d2 != 0), 0, 0 - a/(d2*sqrt(d2))); };",
            "// SpringDamper1D, along z on the signed difference e = z1 - z2 (e0: its value now)",
            "sd1(k, z, l0, e0, z1, z2) = 0, 0, 0 - f, 0, 0, f with { e = z1 - z2; f = k*(e - l0) + z*(e - prev(e0, e)); };",
            "// mi.lib's nonlinear laws in 3-D: its 1-D function f(x1, x2) fed with (d - l0, 0) (a collision: with (0, d)),",
            "// so its delayed inputs give the damper d - d(n-1); its force on mass 1 (2) acts along u",
            "nlAlong(f, l0, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2(d > 0, 0, ((d - l0, 0) : f : (_, !))/d) with { d = sqrt(d2); }; };",
            "nlApart(f, x1, y1, z1, x2, y2, z2) = link(law, x1, y1, z1, x2, y2, z2)",
            "with { law(d2) = select2(d > 0, 0, ((0, d) : f : (!, _))/d) with { d = sqrt(d2); }; };",
            "// Bow3D: mi.lib's nlBow law F(w) on the relative velocity w = (X1 - X1') - (X2 - X2'), against w",
            "bow3(z, scale, profile, ex, ey, ez, x1, y1, z1, x2, y2, z2) = push(wx, wy, wz, s)",
            "with {",
            "  dx = x1 - x2; dy = y1 - y2; dz = z1 - z2;",
            "  wx = dx - prev(ex, dx); wy = dy - prev(ey, dy); wz = dz - prev(ez, dz);",
            "  w = sqrt(wx*wx + wy*wy + wz*wz);",
            "  tip = scale/3; zEnd = z/3;",
            "  f = select2(profile > 0, select2(w < tip, select2(w < scale, 0, tip*z - zEnd*w), (z - zEnd)*w),",
            "    0.63*z*w*exp(-4*pow(w/scale, 2) + 0.5));",
            "  s = select2(w > 0, 0, 0 - f/w);",
            "};",
            "// a plane across one axis at pos, pushing toward its positive side; q0: the mass's coordinate now",
            "plane(k, z, l0, pos, q0, q) = select2(t < 0, 0, 0 - k*t - z*(q - prev(q0, q))) with { t = q - pos - l0; };",
            "");

    static void build(Scene s, Params p, FaustExportOptions o, Network net) {
        int n = s.masses.length;
        int[] pos = new int[n];
        int[][] port = new int[n][3];
        for (int i = 0; i < n; i++) {
            Scene.MassRow m = s.masses[i];
            boolean[] moves = moving(m);
            String[] coords = new String[3];
            for (int a = 0; a < 3; a++) {
                port[i][a] = moves[a] ? net.addPort() : -1;
                coords[a] = moves[a] ? coordinate(s, p, i, a) : lit(m.x0[a]);
                if (moves[a]) {
                    net.addPending(port[i][a], m.f0[a]);
                }
            }
            pos[i] = net.addMass("(" + coords[0] + ",\n    " + coords[1] + ",\n    " + coords[2] + ")", 3);
        }
        for (int j = 0; j < s.links.length; j++) {
            Scene.LinkRow l = s.links[j];
            if (l.type == linkModuleType.PlaneContact3D) {
                String block = "plane(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + p.linkL[j] + ", " + lit(l.planePos)
                        + ", " + lit(s.masses[l.a].x0[l.axis]) + ")";
                net.addLink(block, new int[] {pos[l.a] + l.axis}, new int[] {port[l.a][l.axis]});
                continue;
            }
            net.addLink(linkBlock(s, p, j), new int[] {pos[l.a], pos[l.a] + 1, pos[l.a] + 2, pos[l.b], pos[l.b] + 1,
                pos[l.b] + 2}, new int[] {port[l.a][0], port[l.a][1], port[l.a][2], port[l.b][0], port[l.b][1],
                port[l.b][2]});
        }
        for (FaustExportOptions.Listen li : o.listens()) {
            int i = s.mass(li.mass);
            net.addOutput(pos[i] + li.axis, s.masses[i].x0[li.axis], li.gain);
        }
        for (FaustExportOptions.Input in : o.inputs()) {
            int i = s.mass(in.mass);
            net.addInput(port[i][in.axis], s.forceScale());
        }
    }

    /** @return which coordinates of a mass move */
    private static boolean[] moving(Scene.MassRow m) {
        switch (m.type) {
            case Mass3D:
            case Mass3DSimple:
            case Osc3D:
                return new boolean[] {true, true, true};
            case Mass2DPlane:
                return new boolean[] {true, true, false};
            case Mass1D:
            case Osc1D:
                return new boolean[] {false, false, true};
            default:
                return new boolean[] {false, false, false};
        }
    }

    private static String coordinate(Scene s, Params p, int i, int a) {
        Scene.MassRow m = s.masses[i];
        String q = lit(m.x0[a]) + ", " + lit(m.xr0[a]) + ")";
        switch (m.type) {
            case Osc3D:
            case Osc1D:
                return "osc(" + p.massM[i] + ", " + p.massK[i] + ", " + p.massZ[i] + ", " + lit(s.friction) + ", "
                        + lit(s.g[a]) + ", " + lit(m.rest[a]) + ", " + q;
            case Mass3DSimple:
                return "mass(" + p.massM[i] + ", 0.0, 0.0, " + q;
            default:
                return "mass(" + p.massM[i] + ", " + lit(s.friction) + ", " + lit(s.g[a]) + ", " + q;
        }
    }

    private static String linkBlock(Scene s, Params p, int j) {
        Scene.LinkRow l = s.links[j];
        String d0 = lit(distance(s.masses[l.a].x0, s.masses[l.b].x0));
        if (l.type.isNonlinear() && !l.type.isOneDimensional()) {
            return nonlinear3D(s, p, j, d0);
        }
        switch (l.type) {
            case Spring3D:
                return "spring(" + p.linkK[j] + ", " + p.linkL[j] + ")";
            case Damper3D:
                return "damper(" + p.linkZ[j] + ", " + d0 + ")";
            case SpringDamper3D:
                return "springDamper(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + p.linkL[j] + ", " + d0 + ")";
            case SpringDamper1D:
                return "si.block(2), _, si.block(2), _ : sd1(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + p.linkL[j]
                        + ", " + lit(s.masses[l.a].x0[2] - s.masses[l.b].x0[2]) + ")";
            case Rope3D:
            case Bubble3D:
                return "stretched(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + p.linkL[j] + ", " + d0 + ")";
            case Contact3D:
                return "contact(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + p.linkL[j] + ", " + d0 + ")";
            case Attractor3D:
                return "attractor(" + lit(l.attraction) + ", " + p.linkL[j] + ")";
            default:
                throw new FaustExportException("interaction \"" + l.name + "\"", "no Faust form for " + l.type);
        }
    }

    /**
     * A 3-D nonlinear kind: mi.lib's own function, named with its arguments by the kind's descriptor, applied along
     * the distance ({@code nlAlong}, or {@code nlApart} for a collision); the bow, whose mi.lib function is 1-D in
     * velocity, as its law on the relative velocity vector ({@code bow3}).
     */
    private static String nonlinear3D(Scene s, Params p, int j, String d0) {
        Scene.LinkRow l = s.links[j];
        double[] a = s.masses[l.a].x0, b = s.masses[l.b].x0;
        if (l.type.miLibFunction() == null) {
            return "bow3(" + p.linkZ[j] + ", " + lit(l.extra[0]) + ", " + lit(l.extra[1]) + ", " + lit(a[0] - b[0])
                    + ", " + lit(a[1] - b[1]) + ", " + lit(a[2] - b[2]) + ")";
        }
        boolean collision = l.type.miLibFunction().startsWith("nlCollision");
        String f = MiLibWriter.call(l, p, j) + (collision ? "0.0, 0 - " + d0 : p.linkL[j] + " - " + d0 + ", 0.0") + ")";
        return collision ? "nlApart(" + f + ")" : "nlAlong(" + f + ", " + p.linkL[j] + ")";
    }

    private static double distance(double[] a, double[] b) {
        double dx = a[0] - b[0];
        double dy = a[1] - b[1];
        double dz = a[2] - b[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
