package tactus.internal.calls;

import processing.core.PVector;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;
import tactus.internal.model.ModuleTypes;
import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * The facade calls that look a model up: names, indices and types, the paper engine's index queries, the
 * controllers, the energies. Each enters the model once and hands the work to its room. Not API.
 */
public final class QueryCalls extends Calls {

    public QueryCalls(ModelCore core, ModelLock gate) {
        super(core, gate);
    }



    public int getNumberOfMats() {
        enter();
        try {
            return core.dir.mats.size();
        } finally {
            exit();
        }
    }

    public int getNumberOfLinks() {
        enter();
        try {
            return core.dir.links.size();
        } finally {
            exit();
        }
    }

    public int getMatIndex(String name) {
        enter();
        try {
            int id = core.dir.mats.id(name);
            return id < 0 ? -1 : core.dir.mats.indexOf(id);
        } finally {
            exit();
        }
    }

    public int getLinkIndex(String name) {
        enter();
        try {
            int id = core.dir.links.id(name);
            return id < 0 ? -1 : core.dir.links.indexOf(id);
        } finally {
            exit();
        }
    }

    public int getMass(String name) {
        enter();
        try {
            return core.dir.massId("getMass", name);
        } finally {
            exit();
        }
    }

    public int getInteraction(String name) {
        enter();
        try {
            return core.dir.linkId("getInteraction", name);
        } finally {
            exit();
        }
    }

    public int getInteractionAt(int i) {
        enter();
        try {
            return core.dir.linkAt("getInteractionAt", i);
        } finally {
            exit();
        }
    }

    public String getMatNameAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatNameAt", i, "\"None\" was returned");
            if (id < 0) {
                return "None";
            }
            return core.dir.massName(id);
        } finally {
            exit();
        }
    }

    public String getLinkNameAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkNameAt", i, "\"None\" was returned");
            if (id < 0) {
                return "None";
            }
            return core.dir.linkName(id);
        } finally {
            exit();
        }
    }

    public matModuleType getMatTypeAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatTypeAt", i, "UNDEFINED was returned");
            if (id < 0) {
                return matModuleType.UNDEFINED;
            }
            return ModuleTypes.of(core.dir.massKind(id));
        } finally {
            exit();
        }
    }

    public linkModuleType getLinkTypeAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkTypeAt", i, "UNDEFINED was returned");
            if (id < 0) {
                return linkModuleType.UNDEFINED;
            }
            return ModuleTypes.of(core.dir.linkKind(id));
        } finally {
            exit();
        }
    }

    public String[] getLinkMatNames(String name) {
        enter();
        try {
            int id = core.dir.linkId("getLinkMatNames", name);
            return new String[] {core.dir.massName(core.engine.linkMassA(id)),
                core.dir.massName(core.engine.linkMassB(id))};
        } finally {
            exit();
        }
    }

    public Vect3D getLinkPos1At(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkPos1At", i, "a zero vector was returned");
            if (id < 0) {
                return new Vect3D();
            }
            return core.paper.linkEnd(id, true, new Vect3D());
        } finally {
            exit();
        }
    }

    public Vect3D getLinkPos2At(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkPos2At", i, "a zero vector was returned");
            if (id < 0) {
                return new Vect3D();
            }
            return core.paper.linkEnd(id, false, new Vect3D());
        } finally {
            exit();
        }
    }

    public int getLinkMat1IdxAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkMat1IdxAt", i, "-1 was returned");
            if (id < 0) {
                return -1;
            }
            return core.paper.linkEndIndex(id, true);
        } finally {
            exit();
        }
    }

    public int getLinkMat2IdxAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkMat2IdxAt", i, "-1 was returned");
            if (id < 0) {
                return -1;
            }
            return core.paper.linkEndIndex(id, false);
        } finally {
            exit();
        }
    }

    public String getLinkMat1NameAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkMat1NameAt", i, "\"\" was returned");
            if (id < 0) {
                return "";
            }
            return core.paper.linkEndName(id, true);
        } finally {
            exit();
        }
    }

    public String getLinkMat2NameAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getLinkMat2NameAt", i, "\"\" was returned");
            if (id < 0) {
                return "";
            }
            return core.paper.linkEndName(id, false);
        } finally {
            exit();
        }
    }

    public Vect3D getMatDelayedPosAt(int i) {
        enter();
        try {
            int id = paperMassAt("getMatDelayedPosAt", i, "a zero vector was returned");
            if (id < 0) {
                return new Vect3D();
            }
            return core.paper.delayedPosition(id, new Vect3D());
        } finally {
            exit();
        }
    }

    public PVector getMatForcePVector(int i) {
        enter();
        try {
            return core.state.force(core.dir.massAt("getMatForcePVector", i), new Vect3D()).toPVector();
        } finally {
            exit();
        }
    }

    public double getOsc3DDeltaPos(int i) {
        enter();
        try {
            int id = core.dir.massAt("getOsc3DDeltaPos", i);
            return core.params.paperIsOsc("getOsc3DDeltaPos", id, "0 was returned")
                    ? core.paper.oscDisplacement("getOsc3DDeltaPos", id) : 0;
        } finally {
            exit();
        }
    }

    public int getPlaneOrientationAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getPlaneOrientationAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.paperIsPlane("getPlaneOrientationAt", id) ? core.params.planeAxis("getPlaneOrientationAt",
                    id) : 0;
        } finally {
            exit();
        }
    }

    public double getPlanePositionAt(int i) {
        enter();
        try {
            int id = paperLinkAt("getPlanePositionAt", i, "0 was returned");
            if (id < 0) {
                return 0;
            }
            return core.params.paperIsPlane("getPlanePositionAt", id) ? core.params.planePosition("getPlanePositionAt",
                    id) : 0;
        } finally {
            exit();
        }
    }

    public Vect3D getOscRestPosition(String name) {
        enter();
        try {
            int id = core.dir.massId("getOscRestPosition", name);
            core.params.requireOsc("getOscRestPosition", id);
            return new Vect3D(core.engine.restPosition(id, 0), core.engine.restPosition(id, 1),
                    core.engine.restPosition(id, 2));
        } finally {
            exit();
        }
    }

    public boolean isVelocityControlled(String name) {
        enter();
        try {
            return core.engine.isDriven(core.dir.massId("isVelocityControlled", name));
        } finally {
            exit();
        }
    }

    public String[] getContactGroupSubsets() {
        enter();
        try {
            return core.subsets.contactGroupSubsets();
        } finally {
            exit();
        }
    }

    public void getAllMatsOfType(java.util.ArrayList<PVector> out, matModuleType type) {
        enter();
        try {
            core.paper.massesOfType("getAllMatsOfType", out, null, type, true);
        } finally {
            exit();
        }
    }

    public void createPosSpeedArraysForModType(java.util.ArrayList<PVector> pos, java.util.ArrayList<PVector> vel, matModuleType type) {
        enter();
        try {
            core.paper.massesOfType("createPosSpeedArraysForModType", pos, vel, type, true);
        } finally {
            exit();
        }
    }

    public void getAllMatSpeedsOfType(java.util.ArrayList<PVector> pos, java.util.ArrayList<PVector> vel, matModuleType type) {
        enter();
        try {
            core.paper.massesOfType("getAllMatSpeedsOfType", pos, vel, type, true);
        } finally {
            exit();
        }
    }

    public void updatePosSpeedArraysForModType(java.util.ArrayList<PVector> pos, java.util.ArrayList<PVector> vel, matModuleType type) {
        enter();
        try {
            core.paper.massesOfType("updatePosSpeedArraysForModType", pos, vel, type, false);
        } finally {
            exit();
        }
    }




    public double getKineticEnergy() {
        enter();
        try {
            return core.state.kineticEnergy();
        } finally {
            exit();
        }
    }

    public double getPotentialEnergy() {
        enter();
        try {
            return core.state.potentialEnergy();
        } finally {
            exit();
        }
    }

    public double getTotalEnergy() {
        enter();
        try {
            return core.state.totalEnergy();
        } finally {
            exit();
        }
    }
    /** @return true when a mass or link subset with this name exists. */
    public boolean subsetExists(String subset) {
        enter();
        try {
            return core.subsets.isMatSubset(subset) || core.subsets.isLinkSubset(subset);
        } finally {
            exit();
        }
    }
}
