package tactus.export;

import java.util.ArrayList;
import java.util.List;

import tactus.PhysicalModel;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * The Faust expression of each parameter: a literal of its per-step value, or, for the parameters a slider
 * controls, the slider converted to a per-step value ({@code slider0/1944810000.0} for a stiffness in N/m at
 * 44,100 steps per second).
 */
final class Params {
    final String[] massM;
    final String[] massK;
    final String[] massZ;
    final String[] linkK;
    final String[] linkZ;
    final String[] linkL;
    /** The {@code sliderN = hslider(...);} lines. */
    final List<String> declarations = new ArrayList<>();
    /** True for the parameters a slider controls (index: mass or link). */
    final boolean[] massSlid;
    final boolean[] linkSlid;

    Params(Scene s, PhysicalModel model, FaustExportOptions o) {
        int nm = s.masses.length;
        int nl = s.links.length;
        massM = new String[nm];
        massK = new String[nm];
        massZ = new String[nm];
        massSlid = new boolean[nm];
        for (int i = 0; i < nm; i++) {
            Scene.MassRow r = s.masses[i];
            massM[i] = FaustNumbers.lit(r.m);
            massK[i] = FaustNumbers.lit(r.k);
            massZ[i] = FaustNumbers.lit(r.z);
        }
        linkK = new String[nl];
        linkZ = new String[nl];
        linkL = new String[nl];
        linkSlid = new boolean[nl];
        for (int i = 0; i < nl; i++) {
            Scene.LinkRow r = s.links[i];
            linkK[i] = FaustNumbers.lit(r.k);
            linkZ[i] = FaustNumbers.lit(r.z);
            linkL[i] = FaustNumbers.lit(r.l0);
        }
        int n = 0;
        for (FaustExportOptions.Slider sl : o.sliders()) {
            bind(s, model, sl, "slider" + n++);
        }
    }

    private void bind(Scene s, PhysicalModel model, FaustExportOptions.Slider sl, String id) {
        List<String> names = new ArrayList<>();
        for (String e : sl.elements) {
            if (s.mass(e) >= 0 || s.link(e) >= 0) {
                names.add(e);
            } else {
                String[] members;
                try {
                    members = model.getSubsetMembers(e);
                } catch (IllegalArgumentException ex) {
                    throw new FaustExportException("slider \"" + sl.label + "\"", "\"" + e + "\" is neither a module "
                            + "nor a subset of the model");
                }
                for (String m : members) {
                    names.add(m);
                }
            }
        }
        if (names.isEmpty()) {
            throw new FaustExportException("slider \"" + sl.label + "\"", "its subsets are empty");
        }
        double divisor = divisorOf(s, sl.param);
        double perStep = Double.NaN;
        String expr = divisor == 1 ? id : id + "/" + FaustNumbers.lit(divisor);
        for (String e : names) {
            double v = bindOne(s, sl, e, expr);
            if (Double.isNaN(perStep)) {
                perStep = v;
            } else if (Math.abs(v - perStep) > 1e-12 * Math.max(Math.abs(v), Math.abs(perStep))) {
                throw new FaustExportException("slider \"" + sl.label + "\"", "\"" + e + "\" has " + sl.param + " "
                        + v * divisor + " but \"" + names.get(0) + "\" has " + perStep * divisor
                        + "; a slider sets one value for all its modules");
            }
        }
        double value = perStep * divisor;
        double min = sl.min;
        double max = sl.max;
        if (Double.isNaN(min)) {
            min = FaustExportOptions.MASS.equals(sl.param) ? value / 10 : 0;
            max = value == 0 ? 1 : 2 * Math.abs(value);
        }
        if (value < min || value > max) {
            throw new FaustExportException("slider \"" + sl.label + "\"", "its value now, " + value
                    + ", is outside its range [" + min + ", " + max + "]");
        }
        declarations.add(id + " = hslider(\"" + sl.label + "\", " + FaustNumbers.lit(value) + ", "
                + FaustNumbers.lit(min) + ", " + FaustNumbers.lit(max) + ", " + FaustNumbers.lit((max - min) / 1000)
                + ");");
    }

    /** @return what a parameter in the model's units is divided by to give its per-step value */
    private static double divisorOf(Scene s, String param) {
        if (!s.real) {
            return 1;
        }
        if (FaustExportOptions.STIFFNESS.equals(param)) {
            return (double) s.fs * s.fs;
        }
        if (FaustExportOptions.DAMPING.equals(param)) {
            return s.fs;
        }
        return 1;
    }

    /** Points one module's parameter at the slider; @return its per-step value now. */
    private double bindOne(Scene s, FaustExportOptions.Slider sl, String e, String expr) {
        String why = null;
        int m = s.mass(e);
        if (m >= 0) {
            Scene.MassRow r = s.masses[m];
            boolean osc = r.type == matModuleType.Osc3D || r.type == matModuleType.Osc1D;
            boolean fixed = r.type == matModuleType.Ground3D || r.type == matModuleType.Ground1D;
            massSlid[m] = true;
            switch (sl.param) {
                case FaustExportOptions.MASS:
                    if (!fixed) {
                        massM[m] = expr;
                        return r.m;
                    }
                    why = "a fixed point has no mass";
                    break;
                case FaustExportOptions.STIFFNESS:
                    if (osc) {
                        massK[m] = expr;
                        return r.k;
                    }
                    why = "only oscillators among masses have a stiffness";
                    break;
                case FaustExportOptions.DAMPING:
                    if (osc) {
                        massZ[m] = expr;
                        return r.z;
                    }
                    why = "only oscillators among masses have a damping";
                    break;
                default:
                    why = "a mass has no rest length";
            }
        } else {
            int l = s.link(e);
            Scene.LinkRow r = s.links[l];
            linkSlid[l] = true;
            boolean stiff = r.type != linkModuleType.Damper3D && r.type != linkModuleType.Attractor3D;
            boolean damped = r.type != linkModuleType.Spring3D && r.type != linkModuleType.Attractor3D;
            switch (sl.param) {
                case FaustExportOptions.STIFFNESS:
                    if (stiff) {
                        linkK[l] = expr;
                        return r.k;
                    }
                    why = "a " + r.type + " has no stiffness";
                    break;
                case FaustExportOptions.DAMPING:
                    if (damped) {
                        linkZ[l] = expr;
                        return r.z;
                    }
                    why = "a " + r.type + " has no damping";
                    break;
                case FaustExportOptions.DIST:
                    if (r.type != linkModuleType.Damper3D) {
                        linkL[l] = expr;
                        return r.l0;
                    }
                    why = "a Damper3D has no rest length";
                    break;
                default:
                    why = "an interaction has no mass";
            }
        }
        throw new FaustExportException("slider \"" + sl.label + "\"", "\"" + e + "\": " + why);
    }
}
