package tactus.haptics.inverse;

/** The default mapping of an Inverse3Device, without a connection (for WorkspaceMappingTest). */
public final class Inverse3DeviceDefaults {
    /** The axes spec of the default mapping of the Inverse3 family. */
    public String axes() {
        return Inverse3Device.defaultMappingOfTheFamily().axes();
    }
}
