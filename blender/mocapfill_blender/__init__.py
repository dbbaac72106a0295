"""mocapfill for Blender: fill an animation sketch (a few keyed bones) into a full-body action.

Key some bones of an armature (say hips and legs, every few frames), then Object > Animation >
Fill Action with mocapfill, or the sidebar's mocapfill tab (N panel). The keyed bones keep
their keys; every other bone mocapfill can map is synthesised from a motion database. The
result is a new action, "<action>_filled", assigned to the armature; the original is kept.

From a script: bpy.ops.mocapfill.fill_action(database="", method="hierarchical").
"""
import traceback

import bpy

from . import fill_action, rig_math

bl_info = {
    "name": "mocapfill",
    "author": "mocapfill",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > mocapfill; Object > Animation > Fill Action with mocapfill",
    "description": "Fills a sketch of keyed bones into a full-body animation from a motion capture database",
    "category": "Animation",
}

METHODS = [
    ("hierarchical", "Hierarchical", "Fragments from the database matched limb group by limb group (best overall)"),
    ("fragment", "Fragment", "Whole-body fragments from the database matched to the keys"),
    ("nn", "Nearest neighbour", "The nearest database pose at each frame"),
    ("mean", "Mean", "The database's mean pose for the unkeyed bones"),
    ("pca", "PCA", "Poses from a principal component model of the database"),
    ("hybrid", "Hybrid", "Fragments, corrected by the PCA model"),
]


COVERAGE = [
    ("blend", "Blend", "Where the database does not cover the keyed motion, blend the synthesised bones "
                       "towards the database's mean pose"),
    ("warn", "Warn", "Only report poorly covered stretches; keep the matched motion"),
]


def database_property():
    return bpy.props.StringProperty(
        name="Database", subtype='FILE_PATH', default="",
        description="Motion database: a .mfdb file or a folder of motion files; empty for the default "
                    "database that ships with mocapfill")


def method_property():
    return bpy.props.EnumProperty(name="Method", items=METHODS, default="hierarchical",
                                  description="How the unkeyed bones are synthesised")


def coverage_property():
    return bpy.props.EnumProperty(name="Coverage", items=COVERAGE, default="blend",
                                  description="What to do where the database has no motion like the keys")


class MocapfillSettings(bpy.types.PropertyGroup):
    """The panel's options, saved with the scene."""
    database: database_property()
    method: method_property()
    coverage: coverage_property()


class Progress:
    """The window manager's progress cursor and the status bar, when there is a window
    (there is none in background mode)."""

    def __init__(self, context):
        self.window_manager = context.window_manager if context.window else None
        self.workspace = context.workspace if context.window else None
        if self.window_manager:
            self.window_manager.progress_begin(0, 100)

    def __call__(self, fraction, text):
        if self.window_manager:
            self.window_manager.progress_update(int(100 * fraction))
        if self.workspace:
            self.workspace.status_text_set("mocapfill: " + text)

    def end(self):
        if self.window_manager:
            self.window_manager.progress_end()
        if self.workspace:
            self.workspace.status_text_set(None)


class MOCAPFILL_OT_fill_action(bpy.types.Operator):
    """Fill the active armature's action: keyed bones keep their keys, the other bones are synthesised from a motion database; the result is a new action"""
    bl_idname = "mocapfill.fill_action"
    bl_label = "Fill Action with mocapfill"
    bl_options = {'REGISTER', 'UNDO'}

    database: database_property()
    method: method_property()
    coverage: coverage_property()

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        if obj is None or obj.type != 'ARMATURE':
            cls.poll_message_set("Select an armature with an action")
            return False
        return True

    def execute(self, context):
        progress = Progress(context)
        mocapfill = None
        try:
            from .module_loader import import_mocapfill
            mocapfill = import_mocapfill()
            result = fill_action.fill_active_armature(context, self.database, self.method, self.coverage,
                                                      progress)
        except ImportError as e:
            return self.fail(str(e))
        except rig_math.RigError as e:
            return self.fail("mocapfill: %s" % e)
        except Exception as e:  # noqa: BLE001 - a report, never a traceback, in the UI
            if mocapfill is not None and isinstance(e, mocapfill.Error):
                return self.fail("mocapfill (%s): %s" % (type(e).__name__, e))
            traceback.print_exc()
            return self.fail("mocapfill add-on: unexpected %s: %s (details in the system console)"
                             % (type(e).__name__, e))
        finally:
            progress.end()
        for warning in result.warnings[:5]:
            self.report({'WARNING'}, "mocapfill: %s" % warning)
        self.report({'INFO'}, "mocapfill: %d bones over %d frames into action %r (keys within %.3g deg)"
                    % (len(result.keyed_bones), result.frame_count, result.action.name, result.key_error_max_deg))
        return {'FINISHED'}

    def fail(self, message):
        self.report({'ERROR'}, message)
        return {'CANCELLED'}


class VIEW3D_PT_mocapfill(bpy.types.Panel):
    bl_label = "mocapfill"
    bl_space_type = 'VIEW_3D'
    bl_region_type = 'UI'
    bl_category = "mocapfill"

    def draw(self, context):
        layout = self.layout
        settings = context.scene.mocapfill
        layout.prop(settings, "database")
        layout.prop(settings, "method")
        layout.prop(settings, "coverage")
        obj = context.active_object
        action = obj.animation_data.action if obj and obj.type == 'ARMATURE' and obj.animation_data else None
        layout.label(text="Action: %s" % (action.name if action else "none"), icon='ACTION')
        operator = layout.operator(MOCAPFILL_OT_fill_action.bl_idname, icon='ARMATURE_DATA')
        operator.database = settings.database
        operator.method = settings.method
        operator.coverage = settings.coverage


def draw_animation_menu(self, context):
    self.layout.separator()
    operator = self.layout.operator(MOCAPFILL_OT_fill_action.bl_idname)
    operator.database = context.scene.mocapfill.database  # the sidebar's options
    operator.method = context.scene.mocapfill.method
    operator.coverage = context.scene.mocapfill.coverage


CLASSES = (MocapfillSettings, MOCAPFILL_OT_fill_action, VIEW3D_PT_mocapfill)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.mocapfill = bpy.props.PointerProperty(type=MocapfillSettings)
    bpy.types.VIEW3D_MT_object_animation.append(draw_animation_menu)


def unregister():
    bpy.types.VIEW3D_MT_object_animation.remove(draw_animation_menu)
    del bpy.types.Scene.mocapfill
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
