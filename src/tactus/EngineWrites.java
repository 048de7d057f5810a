package tactus;

/**
 * The engine writes that a parameter or state change is made of, in per-step units: applied at once
 * ({@link #direct}), or recorded into a {@link WriteBatch} that the thread stepping an audio-owned model applies
 * between two steps. The rooms make every such write through {@link ModelCore#writes()}, so the same validation code
 * serves both.
 */
interface EngineWrites {
    void setMass(int id, double m);

    void setOscillator(int id, double k, double z);

    void setLinkParams(int id, double k, double z, double len);

    void setPlanePosition(int id, double pos);

    void setAttraction(int id, double attr);

    void setPosition(int id, double x, double y, double z);

    void setState(int id, double x, double y, double z, double px, double py, double pz);

    void addForce(int id, double fx, double fy, double fz);

    void setInputTarget(int id, double x, double y, double z);

    void setMedium(double gx, double gy, double gz, double friction);

    /** @return writes that go straight to the engine. */
    static EngineWrites direct(tactus.engine.Engine e) {
        return new EngineWrites() {
            public void setMass(int id, double m) {
                e.setMass(id, m);
            }

            public void setOscillator(int id, double k, double z) {
                e.setOscillator(id, k, z);
            }

            public void setLinkParams(int id, double k, double z, double len) {
                e.setLinkParams(id, k, z, len);
            }

            public void setPlanePosition(int id, double pos) {
                e.setPlanePosition(id, pos);
            }

            public void setAttraction(int id, double attr) {
                e.setAttraction(id, attr);
            }

            public void setPosition(int id, double x, double y, double z) {
                e.setPosition(id, x, y, z);
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
