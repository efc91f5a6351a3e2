// Forms generated from the published robot JSON Schema: one section per part, one field per value.
// Nothing here knows a robot part by name, so a component the schema gains shows up by itself;
// which values the robot's drive can use is the page's to say (`offered`).

import { element } from "../dom";

/** The subset of JSON Schema the robot schema uses. */
export interface Schema {
  type?: string | string[];
  description?: string;
  title?: string;
  properties?: Record<string, Schema>;
  required?: string[];
  items?: Schema;
  enum?: unknown[];
  const?: unknown;
  minItems?: number;
  maxItems?: number;
  minimum?: number;
  maximum?: number;
  exclusiveMinimum?: number;
  exclusiveMaximum?: number;
  $ref?: string;
  $defs?: Record<string, Schema>;
}

export type Json = null | boolean | number | string | Json[] | { [key: string]: Json };
export type JsonObject = { [key: string]: Json };

/** A value changed (undefined: removed) at a JSON pointer's path. */
export type ChangeHandler = (path: (string | number)[], value: Json | undefined) => void;

export function pointerOf(path: (string | number)[]): string {
  return path.length === 0 ? "" : "/" + path.join("/");
}

export class SchemaForm {
  /** Input (or section) elements by the JSON pointer of the value they show. */
  readonly fields = new Map<string, HTMLElement>();

  constructor(
    private readonly root: Schema,
    private readonly changed: ChangeHandler,
    /** Redraw the whole form (after a part was added or removed). */
    private readonly rebuild: () => void,
    /** Whether a robot value or part (by its key) is offered; one not offered shows only while set. */
    private readonly offered: (key: string) => boolean = () => true,
  ) {}

  resolve(schema: Schema): Schema {
    if (schema.$ref?.startsWith("#/$defs/")) {
      return this.root.$defs?.[schema.$ref.slice("#/$defs/".length)] ?? {};
    }
    return schema;
  }

  /** The sections of the robot: its plain values first ("Robot"), then one per part. */
  render(document: JsonObject): HTMLElement[] {
    this.fields.clear();
    const plain = element("section", "part");
    plain.dataset.pointer = "";
    plain.append(element("h3", "", this.root.title ?? "Robot"));
    const sections: HTMLElement[] = [plain];
    for (const [key, property] of Object.entries(this.root.properties ?? {})) {
      const schema = this.resolve(property);
      if (schema.const !== undefined) continue; // format and version: not for editing
      const value = document[key];
      const set = value !== undefined && value !== null && !(Array.isArray(value) && value.length === 0);
      if (!this.offered(key) && !(set && isPart(schema, this))) continue; // a part stays while set: it can be removed
      if (isPart(schema, this)) {
        sections.push(this.part(key, schema, document));
      } else {
        plain.append(this.row(key, schema, document[key], [key], this.root.required?.includes(key) ?? false));
      }
    }
    this.fields.set("", plain);
    return sections;
  }

  /** A part: an optional object (added or removed as a whole) or a list of them. */
  private part(key: string, schema: Schema, document: JsonObject): HTMLElement {
    const section = element("section", "part");
    section.dataset.pointer = pointerOf([key]);
    const heading = element("h3", "", titleOf(key));
    section.append(heading);
    if (schema.description) section.append(element("p", "part-description", schema.description));
    this.fields.set(pointerOf([key]), section);
    const value = document[key];
    if (schema.type === "array") {
      const itemSchema = this.resolve(schema.items ?? {});
      const items = Array.isArray(value) ? value : [];
      items.forEach((item, index) => {
        const box = element("fieldset", "part-item");
        box.dataset.pointer = pointerOf([key, index]);
        const legend = element("legend", "", `${singular(titleOf(key))} ${index + 1}`);
        const remove = element("button", "remove", "Remove");
        remove.type = "button";
        remove.addEventListener("click", () => {
          const next = items.filter((_, i) => i !== index);
          this.changed([key], next);
          this.rebuild();
        });
        legend.append(" ", remove);
        box.append(legend, this.objectFields(itemSchema, item, [key, index]));
        this.fields.set(pointerOf([key, index]), box);
        section.append(box);
      });
      const add = element("button", "add", `Add ${singular(titleOf(key)).toLowerCase()}`);
      add.type = "button";
      add.dataset.add = key;
      add.addEventListener("click", () => {
        this.changed([key], [...items, this.template(itemSchema, items.length)]);
        this.rebuild();
      });
      section.append(add);
    } else if (value === undefined) {
      const add = element("button", "add", `Add ${titleOf(key).toLowerCase()}`);
      add.type = "button";
      add.dataset.add = key;
      add.addEventListener("click", () => {
        this.changed([key], this.template(schema, 0));
        this.rebuild();
      });
      section.append(add);
    } else {
      const remove = element("button", "remove", "Remove");
      remove.type = "button";
      remove.addEventListener("click", () => {
        this.changed([key], undefined);
        this.rebuild();
      });
      heading.append(" ", remove);
      section.append(this.objectFields(schema, value, [key]));
    }
    return section;
  }

  private objectFields(schema: Schema, value: Json | undefined, path: (string | number)[]): HTMLElement {
    const box = element("div", "fields");
    const object = isObject(value) ? value : {};
    for (const [key, property] of Object.entries(schema.properties ?? {})) {
      const resolved = this.resolve(property);
      const required = schema.required?.includes(key) ?? false;
      if (resolved.type === "object" || resolved.properties) {
        const nested = element("fieldset", "nested");
        nested.dataset.pointer = pointerOf([...path, key]);
        const legend = element("legend", "", titleOf(key));
        nested.append(legend);
        this.fields.set(pointerOf([...path, key]), nested);
        if (object[key] === undefined) {
          const add = element("button", "add", `Add ${titleOf(key).toLowerCase()}`);
          add.type = "button";
          add.addEventListener("click", () => {
            this.changed([...path, key], this.template(resolved, 0));
            this.rebuild();
          });
          nested.append(add);
        } else {
          const remove = element("button", "remove", "Remove");
          remove.type = "button";
          remove.addEventListener("click", () => {
            this.changed([...path, key], undefined);
            this.rebuild();
          });
          legend.append(" ", remove);
          nested.append(this.objectFields(resolved, object[key], [...path, key]));
        }
        box.append(nested);
      } else if (resolved.type === "array" && isObjectSchema(this.resolve(resolved.items ?? {}))) {
        box.append(this.list(key, resolved, object, path));
      } else {
        box.append(this.row(key, resolved, object[key], [...path, key], required));
      }
    }
    return box;
  }

  /** A list of objects inside a part (an arm's joints). */
  private list(key: string, schema: Schema, owner: JsonObject, path: (string | number)[]): HTMLElement {
    const itemSchema = this.resolve(schema.items ?? {});
    const items = Array.isArray(owner[key]) ? (owner[key] as Json[]) : [];
    const box = element("fieldset", "nested");
    box.dataset.pointer = pointerOf([...path, key]);
    box.append(element("legend", "", titleOf(key)));
    this.fields.set(pointerOf([...path, key]), box);
    items.forEach((item, index) => {
      const inner = element("fieldset", "part-item");
      inner.dataset.pointer = pointerOf([...path, key, index]);
      const legend = element("legend", "", `${singular(titleOf(key))} ${index + 1}`);
      const remove = element("button", "remove", "Remove");
      remove.type = "button";
      remove.addEventListener("click", () => {
        this.changed([...path, key], items.filter((_, i) => i !== index));
        this.rebuild();
      });
      legend.append(" ", remove);
      inner.append(legend, this.objectFields(itemSchema, item, [...path, key, index]));
      this.fields.set(pointerOf([...path, key, index]), inner);
      box.append(inner);
    });
    const add = element("button", "add", `Add ${singular(titleOf(key)).toLowerCase()}`);
    add.type = "button";
    add.dataset.add = pointerOf([...path, key]);
    add.addEventListener("click", () => {
      this.changed([...path, key], [...items, this.template(itemSchema, items.length)]);
      this.rebuild();
    });
    box.append(add);
    return box;
  }

  /** One labelled value: its input, its unit or meaning, and a place for the loader's message. */
  private row(
    key: string,
    schema: Schema,
    value: Json | undefined,
    path: (string | number)[],
    required: boolean,
  ): HTMLElement {
    const row = element("label", "field");
    const name = element("span", "field-name", titleOf(key));
    if (required) name.classList.add("required");
    row.append(name);
    const input = this.input(schema, value, path);
    input.dataset.pointer = pointerOf(path);
    this.fields.set(pointerOf(path), input);
    row.append(input);
    const unit = unitOf(schema);
    if (unit) row.append(element("span", "field-unit", unit));
    row.append(element("span", "field-message"));
    return row;
  }

  private input(schema: Schema, value: Json | undefined, path: (string | number)[]): HTMLElement {
    if (schema.enum) {
      const select = element("select");
      if (value === undefined) select.append(new Option("—", ""));
      for (const option of schema.enum) select.append(new Option(String(option), String(option)));
      select.value = value === undefined ? "" : String(value);
      select.addEventListener("change", () => this.changed(path, select.value === "" ? undefined : select.value));
      return select;
    }
    if (schema.type === "boolean") {
      const box = element("input");
      box.type = "checkbox";
      box.checked = value === true;
      box.addEventListener("change", () => this.changed(path, box.checked));
      return box;
    }
    const input = element("input");
    input.type = "text";
    input.spellcheck = false;
    if (schema.type === "array") {
      // numbers (or names) separated by spaces: a colour, a centre, a range, motor names
      input.value = Array.isArray(value) ? value.map(String).join(" ") : "";
      const numeric = schema.items?.type === "number" || schema.items?.type === "integer";
      input.placeholder = schema.minItems === schema.maxItems && schema.minItems ? `${schema.minItems} values` : "";
      input.addEventListener("change", () => {
        const words = input.value.trim().split(/[\s,]+/).filter((w) => w !== "");
        if (words.length === 0) this.changed(path, schema.minItems ? undefined : []);
        else this.changed(path, words.map((w) => (numeric ? numberOrText(w) : w)));
      });
      return input;
    }
    input.value = value === undefined ? "" : String(value);
    const numeric = schema.type === "number" || schema.type === "integer";
    if (numeric) input.inputMode = "decimal";
    input.addEventListener("change", () => {
      const text = input.value.trim();
      if (text === "") this.changed(path, undefined);
      else this.changed(path, numeric ? numberOrText(text) : input.value);
    });
    return input;
  }

  /** A new part or list item: its required values, each at the least its schema allows. */
  template(schema: Schema, index: number): Json {
    const resolved = this.resolve(schema);
    if (resolved.enum) return resolved.enum[0] as Json;
    if (resolved.type === "object" || resolved.properties) {
      const made: JsonObject = {};
      for (const key of resolved.required ?? []) {
        made[key] = this.template(resolved.properties?.[key] ?? {}, index);
      }
      return made;
    }
    if (resolved.type === "array") {
      return Array.from({ length: resolved.minItems ?? 0 }, () => this.template(resolved.items ?? {}, index));
    }
    if (resolved.type === "string") return `P${index + 1}`;
    if (resolved.type === "boolean") return false;
    if (resolved.type === "integer") return Math.max(resolved.minimum ?? 0, index + 1);
    if (resolved.type === "number") {
      if (resolved.exclusiveMinimum !== undefined) return resolved.exclusiveMinimum + 1;
      if (resolved.minimum !== undefined && resolved.minimum > 0) return resolved.minimum;
      return 0;
    }
    return null;
  }
}

function isObject(value: Json | undefined): value is JsonObject {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function isObjectSchema(schema: Schema): boolean {
  return schema.type === "object" || schema.properties !== undefined;
}

/** A part of the robot: a (possibly absent) object, or a list of objects. */
function isPart(schema: Schema, form: SchemaForm): boolean {
  if (isObjectSchema(schema)) return true;
  return schema.type === "array" && isObjectSchema(form.resolve(schema.items ?? {}));
}

function numberOrText(text: string): Json {
  const value = Number(text);
  // Not a number: sent as typed, so the loader says what it expected.
  return text !== "" && Number.isFinite(value) ? value : text;
}

/** "max_speed" -> "Max speed", "psds" -> "PSDs". */
export function titleOf(key: string): string {
  const special: Record<string, string> = { psds: "PSDs", lidar: "LIDAR", dx: "dx", dy: "dy", dz: "dz" };
  if (special[key]) return special[key];
  const words = key.replace(/_/g, " ");
  return words.charAt(0).toUpperCase() + words.slice(1);
}

function singular(title: string): string {
  if (title === "PSDs") return "PSD";
  return title.endsWith("s") ? title.slice(0, -1) : title;
}

/** The unit or meaning the schema gives a value ("mm forward", "deg/s", "kg"). */
function unitOf(schema: Schema): string {
  return schema.description ?? "";
}
