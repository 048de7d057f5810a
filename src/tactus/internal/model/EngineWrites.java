package tactus.internal.model;

/**
 * The engine writes that a parameter or state change is made of, in per-step units: applied at once
 * ({@link #direct}), or recorded into a {@link WriteBatch} that the thread stepping an audio-owned model applies
 * between two steps. The rooms make every such write through {@link ModelCore#writes()}, so the same validation code
 * serves both. In {@link #setOscillator} and {@link #setLinkParams} a NaN value keeps the value the engine has when
 * the write is applied (public callers reject NaN before), so that two queued changes of one module's different
 * parameters never undo each other.
 */
public interface EngineWrites {
    void setMass(int id, double m);

    void setOscillator(int id, double k, double z);

    void setLinkParams(int id, double k, double z, double len);

    void setPlanePosition(int id, double pos);

    void setAttraction(int id, double attr);

    /** Sets parameter {@code index} beyond K, Z and the length of a link whose kind has it (per step). */
    void setLinkAux(int id, int index, double value);

    void setPosition(int id, double x, double y, double z);

    /** Moves a mass with zero velocity, its links keeping their previous distances (the paper engine's move). */
    void setPositionKeepingLinkHistory(int id, double x, double y, double z);

    void setState(int id, double x, double y, double z, double px, double py, double pz);

    /** Sets the per-step velocity of a mass, keeping the position it has when the write is applied. */
    void setVelocity(int id, double dx, double dy, double dz);

    void addForce(int id, double fx, double fy, double fz);

    void setInputTarget(int id, double x, double y, double z);

    void setMedium(double gx, double gy, double gz, double friction);

    /** @return writes that go straight to the engine. */
    static EngineWrites direct(tactus.engine.Engine e) {
        return new EngineWrites() {
            private final double[] tmp = new double[3];

            public void setVelocity(int id, double dx, double dy, double dz) {
                e.position(id, tmp);
                e.setState(id, tmp[0], tmp[1], tmp[2], tmp[0] - dx, tmp[1] - dy, tmp[2] - dz);
            }

            public void setMass(int id, double m) {
                e.setMass(id, m);
            }

            public void setOscillator(int id, double k, double z) {
                e.setOscillator(id, Double.isNaN(k) ? e.oscStiffness(id) : k, Double.isNaN(z) ? e.oscDamping(id) : z);
            }

            public void setLinkParams(int id, double k, double z, double len) {
                e.setLinkParams(id, Double.isNaN(k) ? e.linkStiffness(id) : k, Double.isNaN(z) ? e.linkDamping(id) : z,
                        Double.isNaN(len) ? e.linkLength(id) : len);
            }

            public void setPlanePosition(int id, double pos) {
                e.setPlanePosition(id, pos);
            }

            public void setAttraction(int id, double attr) {
                e.setAttraction(id, attr);
            }

            public void setLinkAux(int id, int index, double value) {
                e.setLinkAux(id, index, value);
            }

            public void setPosition(int id, double x, double y, double z) {
                e.setPosition(id, x, y, z);
            }

            public void setPositionKeepingLinkHistory(int id, double x, double y, double z) {
                e.setPositionKeepingLinkHistory(id, x, y, z);
            }

            public void setState(int id, double x, double y, double z, double px, double py, double pz) {
                e.setState(id, x, y, z, px, py, pz);
            }

            public void addForce(int id, double fx, double fy, double fz) {
                e.addForce(id, fx, fy, fz);
            }

            public void setInputTarget(int id, double x, double y, double z) {
                e.setInputTarget(id, x, y, z);
            }

            public void setMedium(double gx, double gy, double gz, double friction) {
                e.setGravity(gx, gy, gz);
                e.setFriction(friction);
            }
        };
    }
}
