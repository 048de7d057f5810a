package tactus.internal.calls;


import tactus.internal.model.Check;
import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * The facade calls on module parameters: masses, oscillator stiffness and damping, interaction lengths, stiffness
 * and damping, and the paper's edits by name pattern. Each enters the model once and hands the work to its room.
 * Not API.
 */
public final class ParamCalls extends Calls {
    public ParamCalls(ModelCore core, ModelLock gate) {
        super(core, gate);
    }

    public double getMatMass(String name) {
        enter();
        try {
            return core.params.mass("getMatMass", core.dir.massId("getMatMass", name));
        } finally {
            exit();
        }
    }

    public double getMatMassAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatMassAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.paperMass("getMatMassAt", id);
        } finally {
            exit();
        }
    }

    public void setMatMass(String name, double mass) {
        enterChange();
        try {
            core.params.paperSetMass("setMatMass", core.dir.massId("setMatMass", name), mass);
        } finally {
            exit();
        }
    }

    public void setMatMassAt(int i, double mass) {
        enterChange();
        try {
            core.params.paperSetMass("setMatMassAt", core.dir.massAt("setMatMassAt", i), mass);
        } finally {
            exit();
        }
    }

    public void setMatStiffness(String name, double K) {
        Check.finite("setMatStiffness", name, "K", K);
        enterChange();
        try {
            core.params.setOsc("setMatStiffness", core.dir.massId("setMatStiffness", name), K, Double.NaN);
        } finally {
            exit();
        }
    }

    public void setMatStiffnessAt(int i, double K) {
        Check.finite("setMatStiffnessAt", String.valueOf(i), "K", K);
        enterChange();
        try {
            int id = paperMassAt("setMatStiffnessAt", i, "nothing was changed");
            if (id < 0) {
                return;
            }
            if (core.params.paperIsOsc("setMatStiffnessAt", id, "nothing was changed")) {
                core.params.setOsc("setMatStiffnessAt", id, K, Double.NaN);
            }
        } finally {
            exit();
        }
    }

    public void setMatDamping(String name, double Z) {
        Check.finite("setMatDamping", name, "Z", Z);
        enterChange();
        try {
            core.params.setOsc("setMatDamping", core.dir.massId("setMatDamping", name), Double.NaN, Z);
        } finally {
            exit();
        }
    }

    public void setMatDampingAt(int i, double Z) {
        Check.finite("setMatDampingAt", String.valueOf(i), "Z", Z);
        enterChange();
        try {
            int id = paperMassAt("setMatDampingAt", i, "nothing was changed");
            if (id < 0) {
                return;
            }
            if (core.params.paperIsOsc("setMatDampingAt", id, "nothing was changed")) {
                core.params.setOsc("setMatDampingAt", id, Double.NaN, Z);
            }
        } finally {
            exit();
        }
    }

    public double getMatStiffness(String name) {
        enter();
        try {
            return core.params.oscStiffness("getMatStiffness", core.dir.massId("getMatStiffness", name));
        } finally {
            exit();
        }
    }

    public double getMatStiffnessAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatStiffnessAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.paperIsOsc("getMatStiffnessAt", id, "0 was returned")
                    ? core.params.oscStiffness("getMatStiffnessAt", id) : 0;
        } finally {
            exit();
        }
    }

    public double getMatDamping(String name) {
        enter();
        try {
            return core.params.oscDamping("getMatDamping", core.dir.massId("getMatDamping", name));
        } finally {
            exit();
        }
    }

    public double getMatDampingAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatDampingAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.paperIsOsc("getMatDampingAt", id, "0 was returned")
                    ? core.params.oscDamping("getMatDampingAt", id) : 0;
        } finally {
            exit();
        }
    }

    public double getLinkDistance(String name) {
        enter();
        try {
            return core.params.linkDistance(core.dir.linkId("getLinkDistance", name));
        } finally {
            exit();
        }
    }

    public double getLinkDistanceAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkDistanceAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.linkDistance(id);
        } finally {
            exit();
        }
    }

    public double getLinkElongation(String name) {
        enter();
        try {
            return core.params.linkElongation(core.dir.linkId("getLinkElongation", name));
        } finally {
            exit();
        }
    }

    public double getLinkElongationAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkElongationAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.linkElongation(id);
        } finally {
            exit();
        }
    }

    public double getLinkStiffness(String name) {
        enter();
        try {
            return core.params.linkStiffness(core.dir.linkId("getLinkStiffness", name));
        } finally {
            exit();
        }
    }

    public double getLinkStiffnessAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkStiffnessAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.linkStiffness(id);
        } finally {
            exit();
        }
    }

    public double getLinkDamping(String name) {
        enter();
        try {
            return core.params.linkDamping(core.dir.linkId("getLinkDamping", name));
        } finally {
            exit();
        }
    }

    public double getLinkDampingAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkDampingAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.linkDamping(id);
        } finally {
            exit();
        }
    }

    public double getLinkDRest(String name) {
        enter();
        try {
            return core.params.linkLength(core.dir.linkId("getLinkDRest", name));
        } finally {
            exit();
        }
    }

    public double getLinkDRestAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkDRestAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.linkLength(id);
        } finally {
            exit();
        }
    }

    public void setLinkStiffness(String name, double K) {
        Check.finite("setLinkStiffness", name, "K", K);
        enterChange();
        try {
            core.params.setLink("setLinkStiffness", core.dir.linkId("setLinkStiffness", name), K, Double.NaN,
                    Double.NaN);
        } finally {
            exit();
        }
    }

    public void setLinkStiffnessAt(int i, double K) {
        Check.finite("setLinkStiffnessAt", String.valueOf(i), "K", K);
        enterChange();
        try {
            core.params.setLink("setLinkStiffnessAt", core.dir.linkAt("setLinkStiffnessAt", i), K, Double.NaN,
                    Double.NaN);
        } finally {
            exit();
        }
    }

    public void setLinkDamping(String name, double Z) {
        Check.finite("setLinkDamping", name, "Z", Z);
        enterChange();
        try {
            core.params.setLink("setLinkDamping", core.dir.linkId("setLinkDamping", name), Double.NaN, Z,
                    Double.NaN);
        } finally {
            exit();
        }
    }

    public void setLinkDampingAt(int i, double Z) {
        Check.finite("setLinkDampingAt", String.valueOf(i), "Z", Z);
        enterChange();
        try {
            core.params.setLink("setLinkDampingAt", core.dir.linkAt("setLinkDampingAt", i), Double.NaN, Z,
                    Double.NaN);
        } finally {
            exit();
        }
    }

    public void setLinkDRest(String name, double d) {
        Check.finite("setLinkDRest", name, "d", d);
        enterChange();
        try {
            core.params.setLink("setLinkDRest", core.dir.linkId("setLinkDRest", name), Double.NaN, Double.NaN, d);
        } finally {
            exit();
        }
    }

    public void setLinkDRestAt(int i, double d) {
        Check.finite("setLinkDRestAt", String.valueOf(i), "d", d);
        enterChange();
        try {
            core.params.setLink("setLinkDRestAt", core.dir.linkAt("setLinkDRestAt", i), Double.NaN, Double.NaN, d);
        } finally {
            exit();
        }
    }

    public void setLinkParams(String name, double K, double Z, double dist) {
        Check.finite("setLinkParams", name, "K", K);
        Check.finite("setLinkParams", name, "Z", Z);
        Check.finite("setLinkParams", name, "dist", dist);
        enterChange();
        try {
            core.params.setLink("setLinkParams", core.dir.linkId("setLinkParams", name), K, Z, dist);
        } finally {
            exit();
        }
    }

    public void setMatParamsForName(String tag, double mass) {
        Check.name("setMatParamsForName", tag);
        enterChange();
        try {
            core.paper.setMassForName("setMatParamsForName", tag, mass);
        } finally {
            exit();
        }
    }

    public void setLinkParamsForName(String tag, double K, double Z, double dist) {
        Check.name("setLinkParamsForName", tag);
        Check.finite("setLinkParamsForName", tag, "K", K);
        Check.finite("setLinkParamsForName", tag, "Z", Z);
        Check.finite("setLinkParamsForName", tag, "dist", dist);
        enterChange();
        try {
            core.paper.setLinkParamsForName("setLinkParamsForName", tag, K, Z, dist);
        } finally {
            exit();
        }
    }
}
