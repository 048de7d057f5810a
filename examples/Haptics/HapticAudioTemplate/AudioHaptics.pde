// The audio-haptic machinery of the template: nothing to change here to try a new model.
// Audio: a PhyUGen steps the model once per sample (44.1 kHz) inside Minim's output (LineOut gives a silent
// real-time output when there is no sound card). Haptics: a HapticLoop at 1 kHz on the first Haply found (or
// an emulated one that follows the mouse) hands the device position to the audio thread and takes the force
// on the avatar back through an AvatarExchange, without locks. Drawing: ModelRenderer, from a snapshot.

PhysicalModel mdl;
PhyUGen ugen;
AvatarExchange exchange;
Minim minim;
AudioOutput out;
HaplyConnection haply;
HapticLoop loop;
ModelRenderer renderer;
boolean mouseMovedOnce = false;
double[] handForce = new double[2];
double[] handPosition = new double[2];
float alpha, ox, oy;

void setup() {
  size(900, 500);
  frameRate(60);

  mdl = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
  mdl.setGravity(0);
  mdl.setFriction(0.00001);
  buildModel(mdl);
  mdl.init();

  ugen = new PhyUGen(mdl);
  listen(ugen);
  exchange = new AvatarExchange();
  ugen.attachAvatar("avatar", exchange);
  minim = new Minim(this);
  out = LineOut.open(minim);
  ugen.patch(out);

  // model = (-alpha x + ox, alpha y + oy) for the handle at (x, y) metres; the middle of the workspace
  // (1 cm right of motor 1, 8 cm in front of the motors) is the model's origin
  alpha = ZOOM_MODEL * 100;
  ox = alpha * 0.01;
  oy = -alpha * 0.08;
  haply = HaplyConnection.open(HaplyPreset.HAPLY_2018);
  Device device = new Device((byte) 5, haply.board());
  HaplyPreset.HAPLY_2018.configure(device);
  device.device_set_parameters();
  loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new AvatarLink() {
    public void setTarget(double x, double y, double z) {
      exchange.publishPosition(x, y, z);
    }
    public void takeForce(double[] f) {
      exchange.takeForce(f);
    }
    public void step(int n) {
      // the audio thread steps the model
    }
  });
  loop.setMode(HapticLoop.Mode.AUDIO);
  loop.setPositionGain(alpha);
  loop.setForceGain(FORCE_GAIN);
  loop.setOrigin(ox, oy, 0);
  loop.start();
  registerMethod("dispose", loop);

  renderer = new ModelRenderer(this);
  renderer.setScale(PIXELS_PER_UNIT);
  for (matModuleType t : matModuleType.values()) {
    renderer.setSize(t, 0.012);
    renderer.setScaling(t, 0);
  }
  renderer.setSize(matModuleType.HapticInput3D, 0.08);
  renderer.setColor(matModuleType.Mass2DPlane, 250, 210, 120);
}

void draw() {
  if (haply.isEmulated() && mouseMovedOnce) {
    float mx = (mouseX - width / 2) / PIXELS_PER_UNIT;
    float my = (mouseY - height / 2) / PIXELS_PER_UNIT;
    haply.setHandTarget((ox - mx) / alpha, (my - oy) / alpha);
  }
  background(20, 24, 32);
  pushMatrix();
  translate(width / 2, height / 2);
  renderer.renderModel(mdl);
  loop.devicePosition(handPosition);
  loop.deviceForce(handForce);
  float hx = (float) (-alpha * handPosition[0] + ox) * PIXELS_PER_UNIT;
  float hy = (float) (alpha * handPosition[1] + oy) * PIXELS_PER_UNIT;
  noFill();
  stroke(255);
  strokeWeight(1.5);
  ellipse(hx, hy, 10, 10);
  stroke(255, 230, 90);
  strokeWeight(3);
  line(hx, hy, hx - (float) handForce[0] * 60, hy + (float) handForce[1] * 60);
  popMatrix();

  fill(220);
  textSize(14);
  text("Move the avatar (red) with the Haply, or with the mouse when there is none. Yellow: the force you feel.", 16, 24);
  text("Write your own model in buildModel() in the first tab.", 16, 44);
  text(String.format("force on the handle %.2f N", Math.hypot(handForce[0], handForce[1])), 16, height - 16);
  fill(haply.isEmulated() ? color(255, 170, 60) : color(220));
  text(haply.status(), 16, height - 38);
  if (loop.failure() != null) {
    fill(255, 80, 80);
    text("haptic loop stopped: " + loop.failure(), 16, height - 60);
  }
}

void mouseMoved() {
  mouseMovedOnce = true;
}

void mouseDragged() {
  mouseMovedOnce = true;
}
