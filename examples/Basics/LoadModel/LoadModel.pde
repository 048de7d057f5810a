/*
 * LoadModel: the mobile on the left is read from data/mobile.xml, a model file
 * in the paper engine's XML format. After 1.5 seconds the sketch saves it as it
 * is and loads the file into a second model on the right: the two then move
 * exactly alike, because the file keeps velocities as well as positions and
 * parameters.
 *
 * Units: those of the file (ALGO_UNITS, 1 model unit = 1 pixel, y points up).
 */

import tactus.*;

PhysicalModel mdl;        // the mobile, from data/mobile.xml
PhysicalModel copy;       // the same, saved and reloaded while it moved
PhysicalModel chosen;     // a model being loaded from a file the user picks (key O)
ModelLoader loader;
int simRate = 1000;
int dispRate = 60;
String snapshotFile = "mobile-snapshot.xml";
String message = "";
long stepsDone = 0;       // physics steps run so far

void setup() {
  size(900, 560);
  frameRate(dispRate);
  loader = new ModelLoader(this);
  loadMobile();
}

void loadMobile() {
  mdl = new PhysicalModel(simRate, dispRate);
  loader.loadModel(dataPath("mobile.xml"), mdl);   // also calls mdl.init()
  loader.setIsLoaded(false);                        // getIsLoaded() is for the file chooser below
  copy = null;
  message = "loaded data/mobile.xml: " + mdl.getNumberOfMats() + " masses, " + mdl.getNumberOfLinks() + " links";
}

// Save the running model to a file in the sketch folder, then load that file into a new model.
void saveAndReload() {
  loader.saveModel(snapshotFile, mdl);
  copy = new PhysicalModel(simRate, dispRate);
  loader.loadModel(snapshotFile, copy);
  loader.setIsLoaded(false);
  message = "saved " + snapshotFile + " at frame " + frameCount + " and loaded it on the right";
}

void draw() {
  if (frameCount == 90) {
    saveAndReload();
  }
  // A model the user picked with the file chooser (key O) replaces the mobile once it is loaded.
  if (loader.getIsLoaded() && chosen != null) {
    mdl = chosen;
    chosen = null;
    copy = null;
    loader.setIsLoaded(false);
    message = "loaded the chosen file: " + mdl.getNumberOfMats() + " masses, " + mdl.getNumberOfLinks() + " links";
  }
  // Both models run the same number of steps in every frame, so that they stay in step exactly.
  long due = (long) frameCount * simRate / dispRate;
  int steps = (int) (due - stepsDone);
  stepsDone = due;
  mdl.computeNSteps(steps);
  if (copy != null) {
    copy.computeNSteps(steps);
  }

  background(248);
  drawModel(mdl, 250, color(200, 110, 30));
  if (copy != null) {
    drawModel(copy, 650, color(40, 120, 200));
  }
  fill(20);
  textSize(13);
  textAlign(LEFT, TOP);
  text(message, 12, 10);
  text("left: the model from data/mobile.xml" + (copy == null ? "" : "      right: its copy, saved and reloaded, "
    + (sameState(mdl, copy) ? "in exactly the same state" : "no longer in the same state")), 12, 28);
  text("S: save and reload now   L: load data/mobile.xml again   O: open a model file...", 12, height - 22);
}

// True if every mass of the two models is at exactly the same position (Vect3D.equals compares exactly).
boolean sameState(PhysicalModel a, PhysicalModel b) {
  if (a.getNumberOfMats() != b.getNumberOfMats()) {
    return false;
  }
  for (int i = 0; i < a.getNumberOfMats(); i++) {
    if (!a.getMatPosAt(i).equals(b.getMatPosAt(i))) {
      return false;
    }
  }
  return true;
}

// Draws any model, by module type. The file decides which types appear.
void drawModel(PhysicalModel m, float cx, int massColour) {
  float top = 320;  // screen y of model y = 0
  for (int i = 0; i < m.getNumberOfLinks(); i++) {
    Vect3D a = m.getLinkPos1At(i);
    Vect3D b = m.getLinkPos2At(i);
    switch (m.getLinkTypeAt(i)) {
    case SpringDamper3D:
    case Spring3D:
    case Rope3D:
      stroke(90);
      strokeWeight(1.5);
      line(cx + (float) a.x, top - (float) a.y, cx + (float) b.x, top - (float) b.y);
      break;
    case Contact3D:
      if (m.getLinkDistanceAt(i) < m.getLinkDRestAt(i)) {  // touching: a short red flash
        stroke(230, 40, 40);
        strokeWeight(3);
        line(cx + (float) a.x, top - (float) a.y, cx + (float) b.x, top - (float) b.y);
      }
      break;
    case PlaneContact3D:
      if (m.getPlaneOrientationAt(i) == 1) {
        stroke(120);
        strokeWeight(1);
        float y = top - (float) m.getPlanePositionAt(i);
        line(cx - 180, y, cx + 180, y);
      }
      break;
    case UNDEFINED:
    default:
      break;
    }
  }
  noStroke();
  for (int i = 0; i < m.getNumberOfMats(); i++) {
    Vect3D p = m.getMatPosAt(i);
    float x = cx + (float) p.x;
    float y = top - (float) p.y;
    switch (m.getMatTypeAt(i)) {
    case Ground3D:
    case Ground1D:
      fill(50);
      rect(x - 5, y - 5, 10, 10);
      break;
    case Osc3D:
      fill(130, 80, 200);
      ellipse(x, y, 30, 12);   // the chime
      break;
    default:
      fill(massColour);
      float d = 6 + 5 * (float) Math.sqrt(m.getMatMassAt(i));
      ellipse(x, y, d, d);
      break;
    }
  }
}

void keyPressed() {
  if (key == 's' || key == 'S') {
    saveAndReload();
  } else if (key == 'l' || key == 'L') {
    loadMobile();
  } else if (key == 'o' || key == 'O') {
    // Opens Processing's file chooser; when it closes, load(File) below is called, as in the paper's engine.
    chosen = new PhysicalModel(simRate, dispRate);
    loader.loadModelFromFile(chosen);
  }
}

// Called with the file picked in loadModelFromFile's chooser (null when cancelled); loadModel turns getIsLoaded() true.
void load(File selection) {
  if (selection == null) {
    println("No file was selected");
  } else {
    loader.loadModel(selection.getAbsolutePath(), chosen);
  }
}
